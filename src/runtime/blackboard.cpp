#include "runtime/blackboard.hpp"

#include <algorithm>

namespace uabt::runtime {

Blackboard::Blackboard() {
  scopes_.emplace_back();
}

ScopeId Blackboard::add_scope(ScopeId parent, bool autoremap) {
  Scope scope;
  scope.parent = parent;
  scope.has_parent = true;
  scope.autoremap = autoremap;
  scopes_.push_back(std::move(scope));
  return static_cast<ScopeId>(scopes_.size() - 1);
}

void Blackboard::add_remap(ScopeId scope, std::string key, std::string parent_key) {
  scopes_[scope].remapped[std::move(key)] = std::move(parent_key);
}

SlotId Blackboard::create(ScopeId scope, std::string_view key) {
  const auto slot = static_cast<SlotId>(values_.size());
  values_.emplace_back();
  keys_.emplace_back(key);
  owners_.push_back(scope);
  scopes_[scope].local.emplace(std::string(key), slot);
  journal_.emplace_back(scope, std::string(key));
  return slot;
}

SlotId Blackboard::resolve(ScopeId scope, std::string_view key) {
  // Iterative walk up the scopes: a chain of autoremapped SubTrees may be deep.
  while (true) {
    if (!key.empty() && key.front() == '@') {
      scope = kRootScope;
      key.remove_prefix(1);
      continue;
    }
    Scope& s = scopes_[scope];
    if (auto it = s.local.find(key); it != s.local.end()) return it->second;
    if (s.has_parent) {
      if (auto it = s.remapped.find(key); it != s.remapped.end()) {
        key = it->second;  // stays valid: map nodes are stable
        scope = s.parent;
        continue;
      }
      if (s.autoremap && !is_private_key(key)) {
        scope = s.parent;
        continue;
      }
    }
    return create(scope, key);
  }
}

void Blackboard::set_local(ScopeId scope, std::string_view key, ScriptValue value) {
  auto& local = scopes_[scope].local;
  const auto it = local.find(key);
  const SlotId slot = it != local.end() ? it->second : create(scope, key);
  values_[slot] = std::move(value);
}

std::optional<SlotId> Blackboard::find(ScopeId scope, std::string_view key) const {
  while (true) {
    if (!key.empty() && key.front() == '@') {
      scope = kRootScope;
      key.remove_prefix(1);
      continue;
    }
    const Scope& s = scopes_[scope];
    if (auto it = s.local.find(key); it != s.local.end()) return it->second;
    if (s.has_parent) {
      if (auto it = s.remapped.find(key); it != s.remapped.end()) {
        key = it->second;
        scope = s.parent;
        continue;
      }
      if (s.autoremap && !is_private_key(key)) {
        scope = s.parent;
        continue;
      }
    }
    return std::nullopt;
  }
}

void Blackboard::set(std::string_view key, ScriptValue value) {
  values_[resolve(kRootScope, key)] = std::move(value);
}

const ScriptValue* Blackboard::get(std::string_view key) const {
  const auto slot = find(kRootScope, key);
  if (!slot || values_[*slot].empty()) return nullptr;
  return &values_[*slot];
}

std::vector<std::pair<std::string, ScriptValue>> Blackboard::entries(ScopeId scope) const {
  std::vector<std::pair<std::string, ScriptValue>> out;
  for (const auto& [key, slot] : scopes_[scope].local)
    if (!values_[slot].empty()) out.emplace_back(key, values_[slot]);
  return out;  // std::map iterates in key order
}

void Blackboard::rollback(const Mark& mark) {
  for (std::size_t i = journal_.size(); i > mark.journal; --i) {
    const auto& [scope, key] = journal_[i - 1];
    if (scope < scopes_.size()) scopes_[scope].local.erase(key);
  }
  journal_.resize(mark.journal);
  scopes_.resize(mark.scopes);
  for (std::size_t slot = mark.slots; slot < pending_.size(); ++slot)
    set_pending(static_cast<SlotId>(slot), false);
  if (pending_.size() > mark.slots) pending_.resize(mark.slots);
  values_.resize(mark.slots);
  keys_.resize(mark.slots);
  owners_.resize(mark.slots);
}

void Blackboard::set_pending(SlotId slot, bool pending) {
  if (slot >= pending_.size()) {
    if (!pending) return;
    pending_.resize(values_.size(), 0);
  }
  if (pending_[slot] == static_cast<char>(pending)) return;
  const bool was = pending_[slot] != 0;  // pending or watched
  pending_[slot] = static_cast<char>(pending);
  if (was != pending) pending ? ++pending_count_ : --pending_count_;
}

void Blackboard::set_watched(SlotId slot) {
  if (slot >= pending_.size()) pending_.resize(values_.size(), 0);
  if (pending_[slot] == 0) ++pending_count_;
  pending_[slot] = 2;
}

void Blackboard::clear_pending() {
  std::fill(pending_.begin(), pending_.end(), 0);
  pending_count_ = 0;
}

void Blackboard::resolve_pending(SlotId slot) const {
  if (pending_[slot] == 2) {
    if (resolver_ != nullptr) resolver_->watched(slot);
    return;
  }
  pending_[slot] = 0;
  --pending_count_;
  if (resolver_ != nullptr) resolver_->resolve(slot);
}

}  // namespace uabt::runtime
