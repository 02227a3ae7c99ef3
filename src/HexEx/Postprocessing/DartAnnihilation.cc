#include "DartAnnihilation.hh"

#include "../Core/Prefetch.hh"
#include "../Core/UnionFind.hh"
#include "LocalHexCheck.hh"
#include "LocalVertexCheck.hh"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <new>
#include <system_error>
#include <thread>
#include <utility>

namespace HexEx {

namespace {

// Per-dart flag bits.
constexpr std::uint8_t kQueued = 1;     // on the work list
constexpr std::uint8_t kTouched = 2;    // joined some vertex group (heirs)
constexpr std::uint8_t kSaved = 4;      // links changed at least once; the originals are saved
constexpr std::uint8_t kInCell = 8;     // scratch of countDefectiveHexCells()
constexpr std::uint8_t kCellDone = 16;  // scratch of countDefectiveHexCells(), then of collectHeirs()
// The dart's sign and liveness, copied into the same byte so that a look at a neighbour reads
// one array instead of three (sign, alive, flags); `alive` is still written for the callers.
constexpr std::uint8_t kAlive = 32;     // mirrors alive[d]
constexpr std::uint8_t kAnti = 64;      // sign[d] < 0
constexpr std::uint8_t kRegular = 128;  // sign[d] > 0

/// Rank of a retry that leaves no broken cell but merges vertices (countMergedVertexQuads()):
/// above any count of broken cells.
constexpr long kMergedRank = 1L << 40;

/// A fixed 64-bit mix (splitmix64's finalizer): the alternative orders of the retries.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/// An append-only list kept in blocks of fixed size: growing never copies what is stored
/// and never holds two copies at once (the saved links of a fold-heavy map: 3.5M entries,
/// 70 MB, on the pig folded by 1.5 grid units).
template <class T>
class BlockList {
public:
    /// Number of entries.
    std::size_t size() const { return blocks_.empty() ? 0 : (blocks_.size() - 1) * kBlock + blocks_.back().size(); }
    /// Appends @p v.
    void push_back(const T& v) {
        if (blocks_.empty() || blocks_.back().size() == kBlock) {
            blocks_.emplace_back();
            blocks_.back().reserve(kBlock);
        }
        blocks_.back().push_back(v);
    }
    /// Calls @p f on every entry, in the order they were appended.
    template <class F>
    void forEach(F&& f) const {
        for (const auto& b : blocks_)
            for (const T& e : b) f(e);
    }
    /// Like forEach(), and calls @p ahead on the entry 16 places further on first (to fetch
    /// what @p f will need for it).
    template <class F, class P>
    void forEachAhead(F&& f, P&& ahead) const {
        const std::size_t n = blocks_.empty() ? 0 : (blocks_.size() - 1) * kBlock + blocks_.back().size();
        for (std::size_t i = 0; i < n; ++i) {
            if (i + 16 < n) ahead(at(i + 16));
            f(at(i));
        }
    }

private:
    static constexpr std::size_t kBlock = std::size_t(1) << 16;
    /// Entry @p i in the order of appending.
    const T& at(std::size_t i) const { return blocks_[i / kBlock][i % kBlock]; }
    std::vector<std::vector<T>> blocks_;
};

struct PhasedTwin;

/// The annihilation's state: links, survivors, the saved original links of changed darts
/// and the vertex groups of the heirs.
class Annihilator {
public:
    Annihilator(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign, std::vector<char>& alive, bool heirs,
                bool retries, bool mutual)
        : retries_(retries), mutual_(mutual), alpha_(alpha), sign_(sign), alive_(alive), wantHeirs_(heirs), n_(static_cast<long>(alpha.size())),
          flag_(static_cast<std::size_t>(n_), 0), sameVertex_(0) {
        for (std::size_t d = 0; d < flag_.size(); ++d)
            flag_[d] = static_cast<std::uint8_t>((alive_[d] ? kAlive : 0) | (sign_[d] < 0 ? kAnti : 0) | (sign_[d] > 0 ? kRegular : 0));
    }

    ~Annihilator();

    /// Lists the anti darts alive before the first pass (the retries' orders permute them).
    void listAntis() {
        if (!antis_.empty()) return;
        for (long d = 0; d < n_; ++d)
            if (isAliveAnti(d)) antis_.push_back(static_cast<int>(d));
        if (wantHeirs_) pending_.reserve(antis_.size());  // at most one pair per anti dart
    }

    /// The first pass: every anti dart in ascending order, then the re-queued ones. The pass
    /// walks the list of anti darts (listAntis()), which visits the darts a scan of all darts
    /// for queued anti darts would, in the same order (only processed darts leave the queue,
    /// and re-queued ones wait for the end of the scan), with the links of the darts ahead
    /// prefetched.
    void runAll() {
        listAntis();
        run(&antis_);
    }

    /// Starts the phase-by-phase run on a second thread, on copies of the links and
    /// survivors as they are now (before the first pass), if @p opt asks for it and the map
    /// has enough anti darts (AnnihilationRetry::threads). Returns once the links are copied.
    void startTwin(const AnnihilationRetry& opt);
    /// Stops and drops the phase-by-phase run of startTwin() (the first pass is kept).
    void dropTwin();

    /// Phase by phase: first only partners linked by alpha_0, then alpha_0..1, alpha_0..2 and
    /// all four; in each phase every alive anti dart in ascending order, then the re-queued ones.
    /// This run is the one kept on most heavy folds, so it joins the vertex groups at each
    /// removal, while the pair's links are in the cache, instead of after the run: the same
    /// groups (joinGroups() reads the same links either way: a removed dart's links never
    /// change, not even by AnnihilationRetry::repair, which re-links alive darts only).
    void runPhased() {
        if (wantHeirs_) {
            joinNow_ = true;
            // The list of pending pairs stays empty: give its room (one pair per anti dart,
            // reserved by the first pass) to the union-find, which this run allocates.
            std::vector<std::pair<int, int>>().swap(pending_);
        }
        for (int phase = 0; phase < 4; ++phase) {
            maxLink_ = phase;
            run(&antis_);
        }
        maxLink_ = 3;
    }

    /// If the first pass left broken cells, annihilates again in other orders (see AnnihilationRetry).
    void retry(const AnnihilationRetry& opt, AnnihilationStats& st);

    /// True if the map has at least AnnihilationRetry::phased_first_min_darts darts and its
    /// anti darts are at least AnnihilationRetry::phased_first_share of them.
    bool heavy(const AnnihilationRetry& opt) {
        if (opt.phased_first_share <= 0 || n_ < opt.phased_first_min_darts) return false;
        listAntis();
        return static_cast<double>(antis_.size()) >= opt.phased_first_share * static_cast<double>(n_);
    }

    /// Phase by phase before any other run: true if it is kept as retry() would keep it as
    /// its first retry (judgeRun(), or no broken cell and no merged vertex); otherwise every
    /// dart is put back (restoreAll()) and false.
    bool runPhasedFirst(const AnnihilationRetry& opt, AnnihilationStats& st) {
        runPhased();
        bool kept = false;
        const long now = judgeRun(1, opt, st, kept);
        if (!kept && now == 0) {
            kept = true;
            st.reordered = 1;
            st.broken_cells_after = 0;
        }
        if (!kept) restoreAll();
        return kept;
    }

    /// Fills @p heirs (see annihilateDarts()).
    void collectHeirs(std::vector<std::pair<int, int>>& heirs, const std::function<bool(int, int)>& same_place);

    long pairs = 0;  ///< pairs removed so far

private:
    const bool retries_;  // only the retries need the original links and the anti darts (not the 2D extractor)
    // Every link of the input is mutual (annihilateDarts()'s mutual_links); steps keep it so:
    // x and y are linked to each other or become free or unconnected, and no alive dart
    // links to a removed one.
    const bool mutual_;

    static std::size_t idx(long d) { return static_cast<std::size_t>(d); }
    std::array<int, 4>& A(long d) { return alpha_[idx(d)]; }
    std::uint8_t& F(long d) { return flag_[idx(d)]; }
    bool isAnti(long d) const { return flag_[idx(d)] & kAnti; }
    bool isAlive(long d) const { return flag_[idx(d)] & kAlive; }
    /// Alive and anti.
    bool isAliveAnti(long d) const { return (flag_[idx(d)] & (kAlive | kAnti)) == (kAlive | kAnti); }
    /// Removes @p d (here and in the caller's array).
    void kill(long d) {
        F(d) &= static_cast<std::uint8_t>(~kAlive);
        alive_[idx(d)] = 0;
    }

    /// Called before @p d's links change or it is removed: saves its original links.
    void touch(long d) {
        if (retries_ && !(F(d) & kSaved)) {
            F(d) |= kSaved;
            // The twin (startTwin()) lists only the darts: their original links are those the
            // first pass saved, or still in its arrays if it never changed them.
            if (touchedIds_) touchedIds_->push_back(static_cast<int>(d));
            else saved_.push_back({static_cast<int>(d), A(d)});
        }
    }

    /// Takes over the twin's phase-by-phase run (startTwin()) in place of restoreAll() and
    /// runPhased(): false if there is none or it failed.
    bool takeTwin();

    /// Checks the run of variant @p k (retry()) that just finished: returns its rank (broken
    /// cells among those of the changed darts; kMergedRank + m if it leaves none but merges
    /// vertices) and sets @p kept (with st.reordered and st.broken_cells_after) where it is kept
    /// at once: broken only in alpha_3 (AnnihilationRetry::keep_alpha3_only), or, for phase by
    /// phase (k = 1), repaired by AnnihilationRetry::repair.
    long judgeRun(int k, const AnnihilationRetry& opt, AnnihilationStats& st, bool& kept);

    int idOf(long d) {
        if (sameVertex_.parent.empty()) sameVertex_ = UnionFind(idx(n_));
        F(d) |= kTouched;
        return static_cast<int>(d);
    }

    /// Processes the work list: the alive anti darts of @p order, in that order (nullptr: a
    /// scan of all darts for the ones already queued), and then the darts queued on the way.
    void run(const std::vector<int>* order);

    /// Removes @p anti with a regular partner, if it has one.
    void step(long anti, std::deque<long>& requeued);

    /// Joins the vertex groups of a removed pair (see annihilateDarts()): the pair, and each
    /// of the two with its alpha_1..alpha_3 partners as they are when the pair is removed.
    /// All of these darts end up in one group, so the group's root is found once and every
    /// partner's root linked to it (the smaller root wins, as UnionFind::unite() does: the
    /// groups and their smallest darts are those of uniting pair by pair).
    void joinGroups(long reg, long anti) {
        if (sameVertex_.parent.empty()) sameVertex_ = UnionFind(idx(n_));
        std::vector<int>& parent = sameVertex_.parent;
        int root = sameVertex_.find(idOf(reg));
        auto join = [&](long x) {
            const int r = sameVertex_.find(idOf(x));
            if (r == root) return;
            if (r < root) {
                parent[static_cast<std::size_t>(root)] = r;
                root = r;
            } else {
                parent[static_cast<std::size_t>(r)] = root;
            }
        };
        join(anti);
        for (int j = 1; j < 4; ++j)
            for (const long self : {reg, anti}) {
                const long x = A(self)[j];
                if (x >= 0 && x != reg && x != anti) join(x);
            }
    }

    /// Joins the groups of the pairs whose joining was deferred (pending_), and clears the list.
    void joinPending() {
        const std::size_t n = pending_.size();
        for (std::size_t k = 0; k < n; ++k) {
            if (k + 8 < n) {
                const auto& f = pending_[k + 8];
                prefetch(&A(f.first));
                prefetch(&A(f.second));
                if (!sameVertex_.parent.empty()) {
                    prefetch(&sameVertex_.parent[idx(f.first)]);
                    prefetch(&sameVertex_.parent[idx(f.second)]);
                }
            }
            joinGroups(pending_[k].first, pending_[k].second);
        }
        pending_.clear();
    }

    /// Puts every dart back to its original links, alive and ungrouped (before a retry).
    /// Only touched darts changed: every removed dart and every dart that joined a vertex
    /// group was touched, and each was alive then.
    void restoreAll() {
        // The darts are spread over the arrays: their entries are fetched 16 darts ahead.
        const bool groups = !sameVertex_.parent.empty();
        saved_.forEachAhead(
            [&](const Saved& e) {
                const long d = e.first;
                A(d) = e.second;
                alive_[idx(d)] = 1;
                F(d) = static_cast<std::uint8_t>((F(d) & ~(kQueued | kTouched)) | kAlive);
                if (groups) sameVertex_.parent[idx(d)] = e.first;
            },
            [&](const Saved& e) {
                prefetch(&A(e.first));
                prefetch(&F(e.first));
                prefetch(&alive_[idx(e.first)]);
                if (groups) prefetch(&sameVertex_.parent[idx(e.first)]);
            });
        pending_.clear();
        joinNow_ = false;
        pairs = 0;
    }

    /// Alive darts whose links were changed (the cells a run can have broken are theirs), in
    /// order of their first change (the count of broken cells does not depend on it). The
    /// list of saved darts only grows: it holds the darts changed by this run and by every
    /// run before it. With @p first_entries, only the darts of its first that many entries.
    std::vector<int> changedDarts(std::size_t first_entries = static_cast<std::size_t>(-1)) const {
        std::vector<int> c;
        std::size_t k = 0;
        saved_.forEach([&](const Saved& e) {
            if (k++ < first_entries && alive_[idx(e.first)]) c.push_back(e.first);
        });
        return c;
    }

    /// Alive darts whose alpha_3 link differs from the traced one (only those can join two
    /// vertices while every cell stays a hex).
    std::vector<int> alpha3Changed() const {
        std::vector<int> c;
        saved_.forEach([&](const Saved& e) {
            if (alive_[idx(e.first)] && alpha_[idx(e.first)][3] != e.second[3]) c.push_back(e.first);
        });
        return c;
    }

    /// Broken cells among the cells of the alive darts in @p c (their darts appended to @p bad
    /// if given); with @p stop_after > 0 at most that many are counted.
    long brokenCells(const std::vector<int>& c, std::vector<int>* bad = nullptr, long stop_after = 0) {
        return countDefectiveHexCells(alpha_, alive_, c, flag_, kInCell, kCellDone, bad, stop_after);
    }

    /// True if every broken cell among those of @p c is a hex once the alpha_3 links of the
    /// broken cells' darts are ignored (crossed or partial quads only, which the face repair
    /// and relinking after the annihilation handle; FaceRelinking.hh).
    bool brokenOnlyInAlpha3(const std::vector<int>& c) {
        std::vector<int> bad;
        if (countDefectiveHexCells(alpha_, alive_, c, flag_, kInCell, kCellDone, &bad) == 0) return true;
        std::vector<int> a3(bad.size());
        for (std::size_t k = 0; k < bad.size(); ++k) {
            a3[k] = A(bad[k])[3];
            A(bad[k])[3] = bad[k];
        }
        const long inside = countDefectiveHexCells(alpha_, alive_, bad, flag_, kInCell, kCellDone);
        for (std::size_t k = bad.size(); k-- > 0;) A(bad[k])[3] = a3[k];
        if (inside != 0) return false;
        // The broken cells are hexes inside here, so each is the <alpha_0, alpha_1, alpha_2>
        // orbit of its darts in the list.
        std::map<int, int> cellOf;
        for (const int s : bad) {
            if (cellOf.count(s)) continue;
            const int id = s;
            std::vector<int> stack{s};
            cellOf[s] = id;
            while (!stack.empty()) {
                const int x = stack.back();
                stack.pop_back();
                for (int i = 0; i < 3; ++i) {
                    const int p = A(x)[i];
                    if (p >= 0 && !cellOf.count(p)) {
                        cellOf[p] = id;
                        stack.push_back(p);
                    }
                }
            }
        }
        // Unfixable: a broken cell glued to itself and linked to no other broken cell (the
        // relinking cuts its quads and finds no partner for them). Where several broken cells
        // are linked, the cut quads pair up across them (pig 1.0 seed 5, 1.2 seed 3).
        std::map<int, std::pair<bool, bool>> cellState;  // cell -> (glued to itself, linked to another broken cell)
        for (const int d : bad) {
            const int p = A(d)[3];
            if (p < 0 || p == d) continue;
            const auto it = cellOf.find(p);
            if (it == cellOf.end()) continue;
            auto& st = cellState[cellOf[d]];
            if (it->second == cellOf[d]) st.first = true;
            else st.second = true;
        }
        for (const auto& c : cellState)
            if (c.second.first && !c.second.second) return false;
        return true;
    }

    /// The anti darts alive before the first pass in the alternative order @p k (2:
    /// descending, 3 and more: by a fixed hash).
    std::vector<int> antiOrder(int k) const {
        std::vector<int> o = antis_;
        if (k == 2) std::reverse(o.begin(), o.end());
        if (k >= 3) {
            const std::uint64_t salt = mix(static_cast<std::uint64_t>(k));
            std::vector<std::pair<std::uint64_t, int>> keyed(o.size());
            for (std::size_t i = 0; i < o.size(); ++i) keyed[i] = {mix(static_cast<std::uint64_t>(o[i]) ^ salt), o[i]};
            std::sort(keyed.begin(), keyed.end());
            for (std::size_t i = 0; i < o.size(); ++i) o[i] = keyed[i].second;
        }
        return o;
    }

    std::vector<std::array<int, 4>>& alpha_;
    const std::vector<signed char>& sign_;
    std::vector<char>& alive_;
    const bool wantHeirs_;
    const long n_;
    std::vector<std::uint8_t> flag_;
    // Union-find over all darts, allocated when the first pair annihilates (maps without
    // folds pay nothing). Dense ids cost 4 bytes per dart; a hash map of the touched darts
    // cost about 35 bytes per touched dart, and on fold-heavy maps nearly every dart is touched.
    UnionFind sameVertex_;
    using Saved = std::pair<int, std::array<int, 4>>;
    BlockList<Saved> saved_;  // (dart, original links), in order of first change
    int maxLink_ = 3;                                        // partners are looked for among alpha_0..alpha_maxLink_
    std::vector<int> antis_;                                 // anti darts alive before the first pass
    // Removed pairs (regular, anti) of the current run whose vertex groups are not joined yet
    // (joinGroups() at the end, collectHeirs()); joinNow_: the run joins at once (step()).
    std::vector<std::pair<int, int>> pending_;
    bool joinNow_ = false;
    // Only in the twin (startTwin()): the darts it touched, in order (instead of saved_), and
    // the request to stop.
    std::vector<int>* touchedIds_ = nullptr;
    const std::atomic<bool>* stop_ = nullptr;
    // The phase-by-phase run on a second thread (startTwin()); destroyed first (last member).
    std::unique_ptr<PhasedTwin> twin_;
};

/// The phase-by-phase run on a second thread, beside the first pass (AnnihilationRetry::threads):
/// its own copies of the links and survivors, and the darts it touched in order.
struct PhasedTwin {
    std::vector<std::array<int, 4>> alpha;  ///< links (copied before the first pass)
    std::vector<char> alive;                ///< survivors (the same)
    std::vector<int> touched;               ///< darts touched, in order of their first change
    std::unique_ptr<Annihilator> an;        ///< its state after the run
    std::atomic<bool> stop{false};          ///< set when the first pass is kept
    bool ok = false;                        ///< the run finished (not stopped, no exception)
    std::thread thread;
    ~PhasedTwin() {
        stop = true;
        if (thread.joinable()) thread.join();
    }
};

Annihilator::~Annihilator() = default;

void Annihilator::startTwin(const AnnihilationRetry& opt) {
    listAntis();
    // Worth it where the first pass is long and usually undone (heavy folds: 40 % of the
    // darts are anti darts on the pig folded by 1.5); a retry must be able to run at all.
    if (opt.threads < 2 || !retries_ || opt.orders < 1 || opt.patience < 1 || antis_.empty() ||
        antis_.size() * 8 < static_cast<std::size_t>(n_))
        return;
    // The twin is optional: where its copies cannot be allocated or its thread cannot be
    // started, the retries run one after the other as without it.
    try {
        twin_ = std::make_unique<PhasedTwin>();
        twin_->alive = alive_;
        twin_->alpha = alpha_;  // before the first pass changes them
    } catch (const std::bad_alloc&) {
        twin_.reset();
        return;
    }
    PhasedTwin& t = *twin_;
    try {
        t.thread = std::thread([this, &t]() {
            try {
                t.an = std::make_unique<Annihilator>(t.alpha, sign_, t.alive, wantHeirs_, true, mutual_);
                Annihilator& b = *t.an;
                b.touchedIds_ = &t.touched;
                b.stop_ = &t.stop;
                b.antis_ = antis_;  // read-only in the first pass
                b.runPhased();
                t.ok = !t.stop.load();
            } catch (...) {
                t.ok = false;  // a failed twin is not taken: the retry runs as without it
            }
        });
    } catch (const std::system_error&) {
        twin_.reset();  // no thread: nothing runs on the copies
    }
}

void Annihilator::dropTwin() { twin_.reset(); }

bool Annihilator::takeTwin() {
    if (!twin_) return false;
    std::unique_ptr<PhasedTwin> t = std::move(twin_);
    t->thread.join();
    if (!t->ok) return false;
    Annihilator& b = *t->an;
    // The state restoreAll() and runPhased() would leave. Links, survivors, flags and vertex
    // groups: the twin's (it ran from the same links and survivors as restoreAll() puts
    // back, in the same way). The saved list: the first pass's entries, then those the
    // phased run would append, i.e. the darts it touched that the first pass did not,
    // in the order it touched them, with their original links (the first pass never changed
    // them, so its arrays still hold them). Every saved dart keeps kSaved.
    for (int d : t->touched)
        if (!(F(d) & kSaved)) saved_.push_back({d, A(d)});
    saved_.forEach([&](const Saved& e) { b.flag_[idx(e.first)] |= kSaved; });
    alpha_.swap(t->alpha);
    alive_.swap(t->alive);
    flag_.swap(b.flag_);
    sameVertex_.parent.swap(b.sameVertex_.parent);
    std::vector<std::pair<int, int>>().swap(pending_);
    joinNow_ = b.joinNow_;
    pairs = b.pairs;
    maxLink_ = 3;
    return true;
}

void Annihilator::step(long anti, std::deque<long>& requeued) {
    long reg = -1;
    for (int i = 0; i <= maxLink_ && reg < 0; ++i) {
        const long r = A(anti)[i];
        if (r >= 0 && r != anti && (F(r) & (kAlive | kRegular)) == (kAlive | kRegular)) reg = r;
    }
    if (reg < 0) return;
    touch(reg);
    touch(anti);
    if (wantHeirs_) {
        // The pair's h-vertices merge (paper 4.4.2: a pair linked by alpha_0 joins the
        // vertices of its two darts), and each dart stays with the darts around its
        // h-vertex (alpha_1..alpha_3 partners). The joining is deferred to the end
        // (collectHeirs()), which reads the pair's links then: they are those of now as
        // long as no step writes a link of a removed dart. With involutive links that never
        // happens (a removed dart's partners were re-linked to each other, so no alive dart
        // still links to it), and runs that are undone by a retry then cost no joining at
        // all. Should a step be about to write a removed dart's link (or reg's), the
        // pending pairs are joined first and the rest of the run joins at once.
        if (!joinNow_) {
            for (int j = 0; j < 4 && !joinNow_; ++j) {
                const long x = A(reg)[j], y = A(anti)[j];
                if (x == anti) continue;
                if ((x >= 0 && x != reg && !isAlive(x)) || (y >= 0 && y != anti && (y == reg || !isAlive(y)))) {
                    joinPending();
                    joinNow_ = true;
                }
            }
        }
        if (joinNow_) joinGroups(reg, anti);
        else pending_.emplace_back(static_cast<int>(reg), static_cast<int>(anti));
    }
    for (int j = 0; j < 4; ++j) {
        const long x = A(reg)[j], y = A(anti)[j];
        if (x == anti) continue;
        // x takes y as partner and vice versa; a partner that is one of the removed pair
        // (a free link) turns into a free link of the survivor.
        const bool xs = x >= 0 && x != reg, ys = y >= 0 && y != anti;
        if (xs) touch(x);
        if (ys) touch(y);
        if (xs) A(x)[j] = static_cast<int>(ys ? y : (y < 0 ? -1 : x));
        if (ys) A(y)[j] = static_cast<int>(xs ? x : (x < 0 ? -1 : y));
    }
    kill(reg);
    kill(anti);
    ++pairs;
    // With mutual links, phase 0 of runPhased() (partners by alpha_0 only) needs no work
    // list: its steps never change an alpha_0 link (j = 0 is the pair's own link: x == anti),
    // so a dart it would re-queue was scanned before with the alpha_0 link it has now, had no
    // alive regular partner by it then, and has none now (darts only die); processing it again
    // would change nothing (see the note in run()).
    if (mutual_ && maxLink_ == 0) return;
    // The neighbours may now be regular/anti pairs themselves.
    for (int j = 0; j < 4; ++j)
        for (long nb : {A(reg)[j], A(anti)[j]}) {
            if (nb < 0 || !isAlive(nb)) continue;
            if (isAnti(nb)) {
                // The neighbour itself is the candidate (the same for each of its links).
                if (!(F(nb) & kQueued)) {
                    requeued.push_back(nb);
                    F(nb) |= kQueued;
                }
                continue;
            }
            // With mutual links, a partner m = alpha_k(nb) with k <= maxLink_ is never queued
            // here (see run()): it is skipped unread.
            for (int k = mutual_ ? maxLink_ + 1 : 0; k < 4; ++k) {
                const long m = A(nb)[k];
                if (m >= 0 && isAliveAnti(m) && !(F(m) & kQueued)) {
                    requeued.push_back(m);
                    F(m) |= kQueued;
                }
            }
        }
}

void Annihilator::run(const std::vector<int>* order) {
    std::deque<long> requeued;
    long scan = 0;
    // The scan returns exactly the darts of @p order that are alive anti darts now, in that
    // order: each is queued here, only the scan or the work list unqueues a dart (when it
    // returns it), and a dart re-queued on the way is behind the scan or not in the order.
    // So the dead ones (most of them in the later phases of runPhased()) are left out at
    // once instead of being skipped, with their links prefetched, one by one.
    //
    // Every alive anti dart is in @p order (all of them are in antis_, and a run never makes
    // a dart alive), so an alive anti dart that is not queued was returned earlier in this run
    // and found no alive regular partner among alpha_0..alpha_maxLink_ then; its links have
    // not changed since (a step writes only the links of its neighbours x and y, and
    // re-queues those that are anti darts), and darts only die. With mutual links, a partner
    // m = alpha_k(nb), k <= maxLink_, of an alive regular dart nb has alpha_k(m) = nb: it
    // is dead, regular or queued, never a dart step() would queue; step() skips it unread.
    std::vector<int> live;
    if (order) {
        live.reserve(order->size());
        for (int d : *order)
            if (isAliveAnti(d)) {
                F(d) |= kQueued;
                live.push_back(d);
            }
        order = &live;
    }
    const long end = order ? static_cast<long>(order->size()) : n_;
    auto next = [&]() -> long {
        for (; scan < end; ++scan) {
            if (order) {
                // Retries in a hashed order visit the darts in random memory order: fetch the
                // links of the darts a few steps ahead, and then those of their partners.
                if (scan + 16 < end) {
                    const long f = (*order)[idx(scan + 16)];
                    prefetch(&A(f));
                    prefetch(&F(f));
                }
                if (scan + 8 < end)
                    for (int p : A((*order)[idx(scan + 8)]))
                        if (p >= 0) {
                            prefetch(&A(p));
                            prefetch(&F(p));
                        }
            }
            const long d = order ? (*order)[idx(scan)] : scan;
            if ((F(d) & kQueued) && isAnti(d)) {
                ++scan;
                return d;
            }
        }
        if (requeued.empty()) return -1;
        const long d = requeued.front();
        requeued.pop_front();
        return d;
    };
    unsigned steps = 0;
    for (long anti = next(); anti >= 0; anti = next()) {
        if (stop_ && (++steps & 1023u) == 0 && stop_->load(std::memory_order_relaxed)) return;  // the twin, dropped
        F(anti) &= static_cast<std::uint8_t>(~kQueued);
        if (!isAlive(anti)) continue;
        step(anti, requeued);
    }
}

long Annihilator::judgeRun(int k, const AnnihilationRetry& opt, AnnihilationStats& st, bool& kept) {
    kept = false;
    // The darts of the broken cells are collected once: the checks below (quads only, the
    // repair) need only those cells, not another pass over every changed dart's cell.
    std::vector<int> broken;
    long now = brokenCells(changedDarts(), &broken);
    // A run that leaves no broken cell can still have crossed alpha_3 links around an edge
    // so that two vertices become one (every cell a hex, every vertex link a sphere): such a
    // run ranks below every run that merges none.
    if (now == 0) {
        const long merged = countMergedVertexQuads(alpha_, alive_, alpha3Changed());
        st.merged_vertex_runs += merged > 0 ? 1 : 0;
        if (merged > 0) now = kMergedRank + merged;
    }
    if (opt.keep_alpha3_only && now > 0 && now < kMergedRank && brokenOnlyInAlpha3(broken)) {
        // Only quads are crossed or partial, every cell is a hex inside: the face repair and
        // relinking finish this run; another order would cost a whole run each.
        st.alpha3_only_kept = kept = true;
    } else if (k == 1 && now > 0 && now < kMergedRank && opt.repair && opt.repair(broken)) {
        // The cells phase by phase leaves broken were re-linked into hexes: keep that.
        st.repaired = kept = true;
    }
    if (kept) {
        st.reordered = k;
        st.broken_cells_after = now;
    }
    return now;
}

void Annihilator::retry(const AnnihilationRetry& opt, AnnihilationStats& st) {
    // Whether the first pass left a broken cell decides whether the retries run at all; how
    // many it left matters only where a retry that leaves broken cells (and is not kept at
    // once, below) is compared with it. So the check stops at the first broken cell, and the
    // exact count is taken only when such a comparison needs it, by running the first pass
    // again (restoreAll() puts back every dart it touched: the same run, the same links).
    // The count of a retry that leaves none (0) or merges vertices (kMergedRank + m, above
    // any count of cells) compares the same with any count of at least 1.
    const bool lazy = opt.orders >= 1 && opt.patience >= 1 && !opt.exact_first_count;
    // The darts the first pass changed are the first entries of the saved list; a later run
    // appends the darts it changes first, and its own count covers every saved dart. So the
    // first pass, run again, is counted over its own entries only, as it was the first time.
    const std::size_t firstPassEntries = saved_.size();
    long best0 = brokenCells(changedDarts(), nullptr, lazy ? 1 : 0);
    st.broken_cells_before = st.broken_cells_after = best0;
    if (best0 == 0) return;
    bool best0Exact = !lazy;
    // Variant k: 1 phase by phase (runPhased()), 2 descending, k >= 3 a hashed order.
    auto runVariant = [&](int k) {
        if (k == 1 && takeTwin()) {  // ran beside the first pass (the first variant tried)
            st.phased_beside = true;
            return;
        }
        restoreAll();
        if (k == 0) {
            runAll();
        } else if (k == 1) {
            runPhased();
        } else {
            const std::vector<int> order = antiOrder(k);
            run(&order);
        }
    };
    long best = best0;  // while !best0Exact and bestOrder == 0: a lower bound (1) of the first pass's count
    int bestOrder = 0, lastRun = 0;
    auto exactFirstPass = [&]() {
        runVariant(0);  // changes the same darts as the first time: no entry is appended
        lastRun = 0;
        best0 = brokenCells(changedDarts(firstPassEntries));
        best0Exact = true;
        st.broken_cells_before = best0;
        if (bestOrder == 0) best = best0;
    };
    for (int k = 1; k <= opt.orders && best > 0 && k - bestOrder <= opt.patience; ++k) {
        ++st.retry_runs;
        runVariant(k);
        lastRun = k;
        // (The two ways out of judgeRun() do not read best or bestOrder, so the comparison
        // with the best so far comes after them.)
        bool kept = false;
        const long now = judgeRun(k, opt, st, kept);
        if (kept) return;
        // The next variant starts with restoreAll(), so this run's state is not needed after
        // the comparison: the exact count of the first pass may replace it here.
        if (now > 0 && now < kMergedRank && bestOrder == 0 && !best0Exact) exactFirstPass();
        if (now < best) {
            best = now;
            bestOrder = k;
        }
    }
    if (bestOrder == 0 && !best0Exact) exactFirstPass();  // kept, and its count is reported
    else if (lastRun != bestOrder) runVariant(bestOrder);
    st.reordered = bestOrder;
    st.broken_cells_after = best >= kMergedRank ? 0 : best;
}

void Annihilator::collectHeirs(std::vector<std::pair<int, int>>& heirs, const std::function<bool(int, int)>& same_place) {
    heirs.clear();
    joinPending();
    if (sameVertex_.parent.empty()) return;
    // Smallest surviving dart per group, kept in the union-find's own array: after full
    // compression every dart points at its root (the group's smallest dart, see
    // UnionFind::unite()), and a root with an heir holds -2 - heir.
    std::vector<int>& parent = sameVertex_.parent;
    // Only touched darts can be in a group with others (every dart that joined one was
    // touched, and restoreAll() made the darts of undone runs singletons again), so the
    // others keep parent[d] == d.
    for (long d = 0; d < n_; ++d)
        if (flag_[idx(d)] & kTouched) parent[idx(d)] = sameVertex_.find(static_cast<int>(d));
    auto rootOf = [&](std::size_t d) { return parent[d] < 0 ? d : static_cast<std::size_t>(parent[d]); };
    for (std::size_t d = 0; d < flag_.size(); ++d) {
        if (!(flag_[d] & kTouched) || !alive_[d]) continue;
        const std::size_t r = rootOf(d);
        if (parent[r] >= 0) parent[r] = -2 - static_cast<int>(d);  // darts ascend: the first is the smallest
    }
    auto heirOf = [&](std::size_t d) {
        const int p = parent[rootOf(d)];
        return p < 0 ? -2 - p : -1;
    };
    // (removed dart, heir) in dart order; a dart at the same place as the previous
    // entry with the same heir adds no candidate and is left out.
    auto wanted = [&](std::size_t d, int h, int lastDart, int lastHeir) {
        return !(lastDart >= 0 && h == lastHeir && same_place && same_place(lastDart, static_cast<int>(d)));
    };
    // The first pass decides and counts (for an exact reserve), the second only collects. A
    // removed dart that is not its group's root is read by no other dart (each reads its own
    // entry and its root's), so the first pass leaves the heir in its entry; a root's entry
    // holds -2 - heir already. kCellDone, free again (countDefectiveHexCells() clears it
    // after each call), marks the darts wanted.
    std::size_t count = 0;
    int lastDart = -1, lastHeir = -1;
    for (std::size_t d = 0; d < flag_.size(); ++d) {
        if (!(flag_[d] & kTouched) || alive_[d]) continue;
        const int h = heirOf(d);
        if (h < 0 || !wanted(d, h, lastDart, lastHeir)) continue;
        lastDart = static_cast<int>(d);
        lastHeir = h;
        ++count;
        flag_[d] |= kCellDone;
        if (parent[d] >= 0) parent[d] = h;  // not a root: a root with an heir holds a negative code
    }
    heirs.reserve(count);
    for (std::size_t d = 0; d < flag_.size(); ++d) {
        if (!(flag_[d] & kCellDone)) continue;
        flag_[d] &= static_cast<std::uint8_t>(~kCellDone);
        heirs.emplace_back(static_cast<int>(d), parent[d] >= 0 ? parent[d] : -2 - parent[d]);
    }
}

} // namespace

AnnihilationStats annihilateDarts(std::vector<std::array<int, 4>>& alpha, const std::vector<signed char>& sign,
                                  std::vector<char>& alive, std::vector<std::pair<int, int>>* heirs,
                                  const std::function<bool(int, int)>& same_place, const AnnihilationRetry& retry, bool mutual_links) {
    AnnihilationStats st;
    auto an = std::make_unique<Annihilator>(alpha, sign, alive, heirs != nullptr, retry.enabled, mutual_links);
    // Heavy folds: phase by phase first (AnnihilationRetry::phased_first_share). Where it is
    // not kept, every dart is back as it was, and a fresh start runs as without it.
    if (retry.enabled && retry.orders >= 1 && retry.patience >= 1 && an->heavy(retry)) {
        st.phased_first = an->runPhasedFirst(retry, st);
        if (st.phased_first) {
            st.retry_runs = 1;
        } else {
            an.reset();
            an = std::make_unique<Annihilator>(alpha, sign, alive, heirs != nullptr, retry.enabled, mutual_links);
            st = AnnihilationStats();
        }
    }
    if (!st.phased_first) {
        if (retry.enabled) an->startTwin(retry);
        an->runAll();
        if (retry.enabled && an->pairs > 0) an->retry(retry, st);
        an->dropTwin();  // not taken: the first pass is kept
    }
    st.pairs = an->pairs;
    for (std::size_t d = 0; d < alpha.size(); ++d)
        if (alive[d] && sign[d] < 0) ++st.remaining_anti;
    if (heirs) an->collectHeirs(*heirs, same_place);
    return st;
}

} // namespace HexEx
