// Helpers for the runtime tests: documents from XML text and a World whose leaves follow
// scripted status sequences, recording every tick and halt.
#pragma once
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "bt/xml_io.hpp"
#include "runtime/engine.hpp"
#include "runtime/world.hpp"

namespace uabt::runtime::testing {

constexpr NodeStatus R = NodeStatus::running;
constexpr NodeStatus S = NodeStatus::success;
constexpr NodeStatus F = NodeStatus::failure;
constexpr NodeStatus K = NodeStatus::skipped;
constexpr NodeStatus I = NodeStatus::idle;

// A BT.CPP v4 document from XML text; `body` alone is wrapped as the main tree "Main".
inline bt::Document parse_xml(const std::string& text) {
  std::vector<Finding> findings;
  auto doc = bt::parse_document(text, "test.xml", findings);
  for (const Finding& f : findings)
    ADD_FAILURE() << "test XML: " << f.location.line << ":" << f.location.column << ": "
                  << f.message;
  if (!doc) throw std::runtime_error("test XML does not parse");
  return *doc;
}

inline bt::Document main_tree(const std::string& body, const std::string& more_trees = "") {
  return parse_xml(
      "<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">"
      "<BehaviorTree ID=\"Main\">" +
      body + "</BehaviorTree>" + more_trees + "</root>");
}

// Leaves are keyed by their `name` attribute, or their tag when unnamed. A leaf returns the
// statuses scripted for it, one per tick, repeating the last; unscripted leaves succeed.
class ScriptedWorld : public World {
 public:
  void script(const std::string& leaf, std::vector<NodeStatus> statuses) {
    scripts_[leaf] = std::move(statuses);
    calls_[leaf] = 0;
  }
  int ticks(const std::string& leaf) const { return count(ticks_, leaf); }
  int halts(const std::string& leaf) const { return count(halts_, leaf); }
  // "A" for a tick of A, "~A" for a halt of A, in order.
  std::vector<std::string> events;
  std::string joined_events() const {
    std::string s;
    for (const auto& e : events) s += (s.empty() ? "" : " ") + e;
    return s;
  }
  void clear_events() { events.clear(); }

  std::uint32_t bind_leaf(const LeafBinding& leaf) override {
    keys_.push_back(leaf.info.name.empty() ? leaf.kind : leaf.info.name);
    return static_cast<std::uint32_t>(keys_.size() - 1);
  }
  NodeStatus tick_leaf(const LeafContext& context) override {
    const std::string& key = keys_[context.handle];
    events.push_back(key);
    ++ticks_[key];
    const auto it = scripts_.find(key);
    if (it == scripts_.end() || it->second.empty()) return S;
    const std::size_t n = calls_[key]++;
    return it->second[std::min(n, it->second.size() - 1)];
  }
  void halt_leaf(const LeafContext& context) override {
    const std::string& key = keys_[context.handle];
    events.push_back("~" + key);
    ++halts_[key];
  }

 private:
  static int count(const std::map<std::string, int>& m, const std::string& k) {
    const auto it = m.find(k);
    return it == m.end() ? 0 : it->second;
  }
  std::vector<std::string> keys_;
  std::map<std::string, std::vector<NodeStatus>> scripts_;
  std::map<std::string, std::size_t> calls_;
  std::map<std::string, int> ticks_, halts_;
};

// Records every status change as "name:PREV>NEXT" (name attribute or kind).
class RecordingObserver : public Observer {
 public:
  explicit RecordingObserver(const Engine& engine) : engine_(engine) {}
  void on_status_change(NodeId node, NodeStatus previous, NodeStatus next) override {
    const NodeInfo& i = engine_.info(node);
    changes.push_back((i.name.empty() ? i.kind : i.name) + ":" + status_name(previous) + ">" +
                      status_name(next));
  }
  std::vector<std::string> changes;

 private:
  const Engine& engine_;
};

inline NodeId by_name(const Engine& engine, const std::string& name) {
  const auto found = engine.find_by_name(name);
  if (found.size() != 1) throw std::runtime_error("no single node named " + name);
  return found.front();
}

}  // namespace uabt::runtime::testing
