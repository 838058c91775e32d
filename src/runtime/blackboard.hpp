#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "runtime/script/value.hpp"

namespace uabt::runtime {

using SlotId = std::uint32_t;
using ScopeId = std::uint32_t;
inline constexpr SlotId kNoSlot = UINT32_MAX;

// Gives a pending slot its value when it is first read (Blackboard::set_pending).
class PendingResolver {
 public:
  virtual ~PendingResolver() = default;
  virtual void resolve(SlotId slot) = 0;
  // A watched slot (Blackboard::set_watched) is read.
  virtual void watched(SlotId slot) { (void)slot; }
};

// The blackboards of one engine: one scope per tree instance (the main tree's is the root,
// where the simulated world keeps its state), entries in flat slots.
//
// BT.CPP 4.x rules: a key is looked up locally first; a SubTree port `key="{parent_key}"`
// forwards `key` to the parent; with `_autoremap="true"` every key that is not local and
// does not start with '_' lives in the parent; `@key` is the root's `key`. In BT.CPP these
// rules always land on the same entry for a given (scope, key), so uabt resolves each key
// once, when a node is instantiated, and nodes then read and write slots by index: no string
// lookups while ticking.
class Blackboard {
 public:
  static constexpr ScopeId kRootScope = 0;

  Blackboard();

  ScopeId add_scope(ScopeId parent, bool autoremap);
  // A SubTree port `key="{parent_key}"`.
  void add_remap(ScopeId scope, std::string key, std::string parent_key);
  // The slot `key` names in `scope`, created empty in the scope that owns it if needed.
  SlotId resolve(ScopeId scope, std::string_view key);
  // Sets `key` in `scope` itself, ignoring remapping (a SubTree's literal port value).
  void set_local(ScopeId scope, std::string_view key, ScriptValue value);
  // Same as resolve() without creating anything.
  std::optional<SlotId> find(ScopeId scope, std::string_view key) const;

  // The stored value as it is, pending or not (the world's own bookkeeping, saved states).
  ScriptValue& value(SlotId slot) { return values_[slot]; }
  const ScriptValue& value(SlotId slot) const { return values_[slot]; }
  // The value a node, a script or a port reads: a pending slot is resolved first.
  const ScriptValue& read(SlotId slot) const {
    if (pending_count_ != 0 && slot < pending_.size() && pending_[slot]) resolve_pending(slot);
    return values_[slot];
  }
  ScriptValue& read_for_update(SlotId slot) {
    read(slot);
    return values_[slot];
  }

  // A model checker's on-demand environment: a pending slot has a value that is chosen only
  // when something reads it (`resolver` sets it then), so that values nobody reads in a tick
  // are never enumerated. With no slot pending, read() is value().
  void set_resolver(PendingResolver* resolver) { resolver_ = resolver; }
  void set_pending(SlotId slot, bool pending);
  bool pending(SlotId slot) const { return slot < pending_.size() && pending_[slot] == 1; }
  // The resolver hears of every read of `slot` (its value stays) until clear_pending().
  void set_watched(SlotId slot);
  void clear_pending();
  const std::string& key(SlotId slot) const { return keys_[slot]; }
  ScopeId owner(SlotId slot) const { return owners_[slot]; }
  std::size_t slot_count() const { return values_.size(); }

  // Root-scope access by name (the world state, tests).
  void set(std::string_view key, ScriptValue value);
  const ScriptValue* get(std::string_view key) const;  // nullptr when absent or empty
  // Entries of one scope that hold a value, sorted by key.
  std::vector<std::pair<std::string, ScriptValue>> entries(ScopeId scope = kRootScope) const;

  // Undo support for a failed instantiation (hot swap): everything created after mark().
  struct Mark {
    std::size_t scopes = 0, slots = 0, journal = 0;
  };
  Mark mark() const { return {scopes_.size(), values_.size(), journal_.size()}; }
  void rollback(const Mark& mark);

 private:
  struct Scope {
    ScopeId parent = kRootScope;
    bool has_parent = false;
    bool autoremap = false;
    std::map<std::string, SlotId, std::less<>> local;
    std::map<std::string, std::string, std::less<>> remapped;
  };
  SlotId create(ScopeId scope, std::string_view key);
  void resolve_pending(SlotId slot) const;

  std::vector<Scope> scopes_;
  std::vector<ScriptValue> values_;
  std::vector<std::string> keys_;
  std::vector<ScopeId> owners_;
  std::vector<std::pair<ScopeId, std::string>> journal_;  // slots created in existing scopes
  // Pending slots: a read resolves them (logically the value was there all along).
  mutable std::vector<char> pending_;
  mutable std::size_t pending_count_ = 0;
  PendingResolver* resolver_ = nullptr;
};

inline bool is_private_key(std::string_view key) {
  return !key.empty() && key.front() == '_';
}

}  // namespace uabt::runtime
