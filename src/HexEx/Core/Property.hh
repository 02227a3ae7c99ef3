#pragma once
/// @file Property.hh
/// @ingroup kernel
/// Typed property containers per entity kind, requested by name or kept by handle
/// (the OpenVolumeMesh property idea, reduced to what the extractor needs).

#include "Handles.hh"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

namespace HexEx {

/// Tag of per-cell-corner entities: index 4*c+i is corner i of tet c.
struct CellCornerTag {};
/// Handle of a corner of a tet (4*cell + corner).
using CellCornerHandle = Handle<CellCornerTag>;

/// Type-erased base of a property, so a manager can resize all of them together.
class BasePropertyStorage {
public:
    virtual ~BasePropertyStorage() = default;
    /// Resize to @p n entities.
    virtual void resize(std::size_t n) = 0;
    /// Name given when the property was requested.
    virtual const std::string& name() const = 0;
    /// The C++ type stored.
    virtual const std::type_info& type() const = 0;
};

/// Storage of one property: a value of type T per entity of kind Tag.
template <class T, class Tag>
class PropertyStorage final : public BasePropertyStorage {
public:
    /// Storage for @p n entities, each set to @p def.
    PropertyStorage(std::string name, std::size_t n, T def) : name_(std::move(name)), def_(def), data_(n, def) {}
    void resize(std::size_t n) override { data_.resize(n, def_); }
    const std::string& name() const override { return name_; }
    const std::type_info& type() const override { return typeid(T); }
    /// The values, indexed by entity index.
    std::vector<T>& data() { return data_; }

private:
    std::string name_;
    T def_;
    std::vector<T> data_;
};

/// A handle to a property: cheap to copy, shares the storage with the mesh.
template <class T, class Tag>
class Property {
public:
    /// Null property.
    Property() = default;
    /// Wraps a storage.
    explicit Property(std::shared_ptr<PropertyStorage<T, Tag>> s) : s_(std::move(s)) {}
    /// Value of entity @p h.
    typename std::vector<T>::reference operator[](Handle<Tag> h) { return s_->data()[h.uidx()]; }
    /// Value of entity @p h.
    typename std::vector<T>::const_reference operator[](Handle<Tag> h) const { return s_->data()[h.uidx()]; }
    /// Number of entities.
    std::size_t size() const { return s_->data().size(); }
    /// True if it refers to a storage.
    bool is_valid() const { return static_cast<bool>(s_); }
    /// Direct access to the array (for fast loops).
    std::vector<T>& data() { return s_->data(); }

private:
    std::shared_ptr<PropertyStorage<T, Tag>> s_;
};

/// Per-entity-kind property manager. Properties follow the entity count through resize().
template <class Tag>
class PropertyManager {
public:
    /// Returns the property named @p name, creating it with default @p def if absent.
    /// Throws std::logic_error if a property of that name exists with another type.
    template <class T>
    Property<T, Tag> request(const std::string& name, const T& def = T()) {
        auto it = props_.find(name);
        if (it != props_.end()) {
            auto typed = std::dynamic_pointer_cast<PropertyStorage<T, Tag>>(it->second);
            if (!typed) throw std::logic_error("property '" + name + "' exists with another type");
            return Property<T, Tag>(typed);
        }
        auto s = std::make_shared<PropertyStorage<T, Tag>>(name, n_, def);
        props_[name] = s;
        return Property<T, Tag>(s);
    }
    /// True if a property named @p name exists.
    bool exists(const std::string& name) const { return props_.count(name) > 0; }
    /// The values of the property named @p name if it exists with type T, else nullptr.
    template <class T>
    const std::vector<T>* find(const std::string& name) const {
        auto it = props_.find(name);
        if (it == props_.end()) return nullptr;
        auto typed = std::dynamic_pointer_cast<PropertyStorage<T, Tag>>(it->second);
        return typed ? &typed->data() : nullptr;
    }
    /// Removes the property named @p name (handles already taken keep their storage alive).
    void remove(const std::string& name) { props_.erase(name); }
    /// Resizes every property to @p n entities.
    void resize(std::size_t n) {
        n_ = n;
        for (auto& p : props_) p.second->resize(n);
    }

private:
    std::size_t n_ = 0;
    std::map<std::string, std::shared_ptr<BasePropertyStorage>> props_;
};

} // namespace HexEx
