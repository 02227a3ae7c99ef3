#pragma once
/// @file ReportStage.hh
/// @ingroup pipeline
/// Pipeline stage "report": each stage's counts and warnings go into the ExtractionReport
/// as the data flows (one function per stage output, called in pipeline order).

#include "../Extraction/ExtractionReport.hh"
#include "AnnihilateStage.hh"
#include "ArcStage.hh"
#include "AssembleStage.hh"
#include "ConnectStage.hh"
#include "DartStage.hh"
#include "PreprocessStage.hh"

namespace HexEx {

/// Input statistics and warnings of the preprocessing.
void addToReport(const PreprocessOutput& out, ExtractionReport& rep);
/// Extracted and anti dart counts.
void addToReport(const DartStageOutput& out, ExtractionReport& rep);
/// Links cut as one-sided.
void addToReport(const ConnectOutput& out, ExtractionReport& rep);
/// Annihilated pairs and remaining anti darts.
void addToReport(const AnnihilateOutput& out, ExtractionReport& rep);
/// Unconnected darts, repaired face connections and their warning.
void addToReport(const MapOutput& out, ExtractionReport& rep);
/// Implicit cells built by the fast path.
void addToReport(const ImplicitCells& cells, ExtractionReport& rep);
/// Output counts, validation, warnings and the final verdict valid_all_hex (needs the
/// annihilation counts already in @p rep).
void addToReport(const AssembleOutput& out, ExtractionReport& rep);

/// Edge and face counts of the arcs stage, its failures and their warning.
void addToReport(const HexArcs& arcs, ExtractionReport& rep);

} // namespace HexEx
