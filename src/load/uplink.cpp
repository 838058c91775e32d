#include "load/uplink.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "base/files.hpp"
#include "base/json_input.hpp"
#include "base/suggest.hpp"
#include "fretish/json_positions.hpp"

namespace uabt::load {

namespace {

using Json = nlohmann::ordered_json;

// Finds `"text"` in the file at or after `from`; the position of its first character.
struct Locator {
  const std::string& text;
  const std::string& file;

  std::size_t offset_of(const std::string& key, std::size_t from) const {
    const std::size_t at = text.find("\"" + key + "\"", from);
    return at == std::string::npos ? from : at;
  }
  // The same, as an object key (followed by ':'), not a string value that happens to match:
  // in {"A": {"before": "B"}, "B": …} the key "B" is the second "B".
  std::size_t key_offset(const std::string& key, std::size_t from) const {
    const std::string quoted = "\"" + key + "\"";
    for (std::size_t at = text.find(quoted, from); at != std::string::npos;
         at = text.find(quoted, at + 1)) {
      const std::size_t after = text.find_first_not_of(" \t\r\n", at + quoted.size());
      if (after != std::string::npos && text[after] == ':') return at;
    }
    return from;
  }
  SourceLocation at(std::size_t offset) const {
    const auto p = fretish::detail::position_of(text, offset);
    return {file, p.line, p.column};
  }
};

void invalid(std::vector<Finding>& findings, std::string message, SourceLocation location) {
  findings.push_back(make_finding("uplink-invalid", std::move(message), std::move(location)));
}

void read_place(const Json& place, const Locator& where, std::size_t from, UplinkPlan& plan,
                std::vector<Finding>& findings) {
  if (!place.is_object()) {
    invalid(findings, "\"place\" must be an object: {\"Storm\": {\"before\": \"Req2\"}}",
            where.at(from));
    return;
  }
  for (const auto& [id, spec] : place.items()) {
    const std::size_t key_at = where.key_offset(id, from);
    Placement p;
    p.requirement = id;
    p.location = where.at(key_at);
    std::size_t given = 0;
    bool reported = false;
    if (spec.is_object()) {
      for (const auto& [relation, anchor] : spec.items()) {
        const std::size_t relation_at = where.key_offset(relation, key_at);
        if ((relation != "before" && relation != "after") || !anchor.is_string()) {
          invalid(findings,
                  "placement of '" + id +
                      "': expected \"before\" or \"after\" with a requirement id, found \"" +
                      relation + "\"",
                  where.at(relation_at));
          reported = true;
          continue;
        }
        ++given;
        p.relation = relation;
        p.anchor = anchor.get<std::string>();
        p.anchor_location = where.at(where.offset_of(p.anchor, relation_at));
      }
    }
    if (given == 1 && !reported) {
      plan.place.push_back(std::move(p));
    } else if (!reported) {
      invalid(findings,
              "placement of '" + id + "' needs exactly one of \"before\" or \"after\": {\"" + id +
                  "\": {\"before\": \"Req2\"}}",
              p.location);
    }
    from = key_at + 1;
  }
}

void read_remove(const Json& remove, const Locator& where, std::size_t from, UplinkPlan& plan,
                 std::vector<Finding>& findings) {
  if (!remove.is_array()) {
    invalid(findings, "\"remove\" must be a list of requirement ids: [\"Req3\"]", where.at(from));
    return;
  }
  for (const auto& item : remove) {
    if (!item.is_string()) {
      invalid(findings,
              "\"remove\" holds " + std::string(item.type_name()) +
                  ", expected requirement ids (strings)",
              where.at(from));
      continue;
    }
    const std::string id = item.get<std::string>();
    const std::size_t at = where.offset_of(id, from);
    plan.remove.push_back({id, where.at(at)});
    from = at + 1;
  }
}

// "retire" / "weaken": {"Id": "why"}: the reason is what the report shows, so it is required.
void read_consent(const std::string& kind, const Json& entries, const Locator& where,
                  std::size_t from, UplinkPlan& plan, std::vector<Finding>& findings) {
  if (!entries.is_object()) {
    invalid(findings,
            "\"" + kind +
                "\" must be an object of guarantee ids and reasons: {\"HammerPower\": "
                "\"the hammer is broken\"}",
            where.at(from));
    return;
  }
  for (const auto& [id, reason] : entries.items()) {
    const std::size_t at = where.offset_of(id, from);
    if (!reason.is_string() || reason.get<std::string>().empty()) {
      invalid(findings,
              "\"" + kind + "\" needs a reason for '" + id + "': {\"" + id +
                  "\": \"why it may stop holding\"}",
              where.at(at));
    } else {
      plan.consent.push_back({"", id, kind, reason.get<std::string>(), where.at(at)});
    }
    from = at + 1;
  }
}

std::vector<std::string> ids_of(const std::vector<fretish::Requirement>& requirements) {
  std::vector<std::string> ids;
  for (const auto& r : requirements) ids.push_back(r.id);
  return ids;
}

std::vector<fretish::Requirement>::iterator find_id(std::vector<fretish::Requirement>& list,
                                                    const std::string& id) {
  return std::find_if(list.begin(), list.end(),
                      [&](const fretish::Requirement& r) { return r.id == id; });
}

void unknown_id(Mission& m, const std::string& message, const std::string& id,
                const std::vector<std::string>& known, const SourceLocation& location) {
  Finding f = make_finding("uplink-invalid", message, location);
  if (std::string hint = did_you_mean(id, known); !hint.empty()) f.notes.push_back(std::move(hint));
  m.findings.push_back(std::move(f));
}

UplinkMerge record_of(const std::string& package, const std::string& id, const std::string& rule,
                      const SourceLocation& location) {
  UplinkMerge record;
  record.package = package;
  record.requirement = id;
  record.rule = rule;
  record.location = location;
  return record;
}

std::string adaptable_of(const fretish::Requirement& r) {
  return r.scope ? r.scope->mode : std::string();
}

// Placements that anchor one another in a circle (A before B, B before A; or longer) cannot
// all hold, or tie nothing to the rest of the order: one `uplink-invalid` error per circle, at
// the entry that closes it (the last in the file), naming the circle. What is left, in file
// order, can all be applied.
std::vector<const Placement*> without_cycles(const std::vector<const Placement*>& placements,
                                             std::vector<Finding>& findings) {
  std::map<std::string, std::size_t> index_of;  // requirement → its placement
  for (std::size_t k = 0; k < placements.size(); ++k)
    index_of.emplace(placements[k]->requirement, k);
  std::vector<bool> in_cycle(placements.size(), false);
  for (std::size_t start = 0; start < placements.size(); ++start) {
    if (in_cycle[start]) continue;
    std::vector<std::size_t> walk{start};
    for (auto next = index_of.find(placements[start]->anchor);
         next != index_of.end() && walk.size() <= placements.size();
         next = index_of.find(placements[walk.back()]->anchor)) {
      if (next->second == start) break;
      walk.push_back(next->second);
    }
    const auto closing = index_of.find(placements[walk.back()]->anchor);
    if (closing == index_of.end() || closing->second != start) continue;
    bool same_relation = true;
    std::string circle;
    for (std::size_t k : walk) {
      in_cycle[k] = true;
      const Placement& p = *placements[k];
      same_relation &= p.relation == placements[start]->relation;
      circle += (circle.empty() ? "" : ", ") + p.requirement + " " + p.relation + " " + p.anchor;
    }
    const Placement& last = *placements[*std::max_element(walk.begin(), walk.end())];
    invalid(findings,
            "uplink.json places '" + last.requirement + "' " + last.relation + " '" + last.anchor +
                "', which closes a cycle of placements (" + circle + "): " +
                (same_relation ? "no order satisfies them all"
                               : "they place one another and nothing places them among the "
                                 "other requirements"),
            last.location);
  }
  std::vector<const Placement*> kept;
  for (std::size_t k = 0; k < placements.size(); ++k)
    if (!in_cycle[k]) kept.push_back(placements[k]);
  return kept;
}

}  // namespace

UplinkPlan read_uplink_plan(const std::filesystem::path& path, const std::string& shown,
                            std::vector<Finding>& findings) {
  UplinkPlan plan;
  std::string error;
  const auto text = read_text_file(path, error);
  if (!text) {
    findings.push_back(make_finding("load-file", shown + ": " + error, {shown, 0, 0}));
    return plan;
  }
  const Locator where{*text, shown};
  JsonInputError json_error;
  std::optional<Json> parsed = parse_json_input<Json>(*text, json_error);
  if (!parsed) {
    invalid(findings, "uplink.json: " + json_error.message, where.at(json_error.offset));
    return plan;
  }
  const Json root = std::move(*parsed);
  if (!root.is_object()) {
    invalid(findings,
            "uplink.json must be an object: {\"place\": {\"Storm\": {\"before\": \"Req2\"}}, "
            "\"remove\": [\"Req3\"]}",
            where.at(0));
    return plan;
  }
  for (const auto& [key, value] : root.items()) {
    const std::size_t at = where.key_offset(key, 0);
    if (key == "place")
      read_place(value, where, at, plan, findings);
    else if (key == "remove")
      read_remove(value, where, at, plan, findings);
    else if (key == "retire" || key == "weaken")
      read_consent(key, value, where, at, plan, findings);
    else
      invalid(findings,
              "unknown key \"" + key +
                  "\" in uplink.json: expected \"place\", \"remove\", \"retire\" or \"weaken\"",
              where.at(at));
  }
  return plan;
}

void merge_requirements(Mission& m, std::vector<fretish::Requirement> incoming,
                        const UplinkPlan& plan, const std::string& package) {
  const std::vector<std::string> incoming_ids = ids_of(incoming);
  std::vector<std::string> removed;
  for (const auto& rem : plan.remove) {
    if (std::find(incoming_ids.begin(), incoming_ids.end(), rem.requirement) !=
        incoming_ids.end()) {
      invalid(m.findings,
              "uplink.json removes '" + rem.requirement + "', which this package also uplinks",
              rem.location);
      continue;
    }
    auto it = find_id(m.requirements, rem.requirement);
    if (it == m.requirements.end()) {
      unknown_id(m,
                 "uplink.json removes '" + rem.requirement + "', which the mission does not have",
                 rem.requirement, ids_of(m.requirements), rem.location);
      continue;
    }
    UplinkMerge record = record_of(package, rem.requirement, "removed", rem.location);
    record.adaptable = adaptable_of(*it);
    m.merges.push_back(std::move(record));
    removed.push_back(rem.requirement);
    m.requirements.erase(it);
  }

  const std::size_t first_record = m.merges.size();
  for (auto& r : incoming) {
    auto same = find_id(m.requirements, r.id);
    m.merges.push_back(record_of(
        package, r.id, same == m.requirements.end() ? "appended" : "replaced", r.location));
    if (same != m.requirements.end()) {
      *same = std::move(r);
      continue;
    }
    // Last before the node's default, in the list too, so that the list reads in priority order.
    const std::string node = adaptable_of(r);
    auto fallback = std::find_if(m.requirements.begin(), m.requirements.end(),
                                 [&](const fretish::Requirement& old) {
                                   return !node.empty() && adaptable_of(old) == node &&
                                          old.conditions.empty() && !r.conditions.empty();
                                 });
    m.requirements.insert(fallback, std::move(r));
  }

  // Placements that name ids the merged mission has.
  std::vector<const Placement*> valid;
  for (const auto& p : plan.place) {
    if (find_id(m.requirements, p.requirement) == m.requirements.end()) {
      unknown_id(m,
                 "uplink.json places '" + p.requirement +
                     "', which neither this package nor the mission has",
                 p.requirement, ids_of(m.requirements), p.location);
      continue;
    }
    if (p.anchor == p.requirement) {
      invalid(m.findings, "uplink.json places '" + p.requirement + "' " + p.relation + " itself",
              p.anchor_location);
      continue;
    }
    if (find_id(m.requirements, p.anchor) == m.requirements.end()) {
      const bool gone = std::find(removed.begin(), removed.end(), p.anchor) != removed.end();
      unknown_id(
          m,
          "uplink.json places '" + p.requirement + "' " + p.relation + " '" + p.anchor + "', " +
              (gone ? "which this package removes" : "which the merged mission does not have"),
          p.anchor, gone ? std::vector<std::string>{} : ids_of(m.requirements), p.anchor_location);
      continue;
    }
    valid.push_back(&p);
  }
  const std::vector<const Placement*> applied = without_cycles(valid, m.findings);

  // Every placed requirement is taken out, then put back beside its anchor, anchors first:
  // later insertions never move earlier ones, so every placement holds in the end.
  std::map<std::string, const Placement*> placement_of;
  std::map<std::string, fretish::Requirement> taken;
  for (const Placement* p : applied) {
    placement_of[p->requirement] = p;
    auto placed = find_id(m.requirements, p->requirement);
    taken.emplace(p->requirement, std::move(*placed));
    m.requirements.erase(placed);
  }
  for (const Placement* first : applied) {
    std::vector<const Placement*> chain;  // `first`, its anchor's placement, and so on
    for (const Placement* p = first; p != nullptr && taken.count(p->requirement);) {
      chain.push_back(p);
      const auto next = placement_of.find(p->anchor);
      p = next == placement_of.end() ? nullptr : next->second;
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const Placement& p = **it;
      auto anchor = find_id(m.requirements, p.anchor);
      m.requirements.insert(p.relation == "before" ? anchor : anchor + 1,
                            std::move(taken.at(p.requirement)));
      taken.erase(p.requirement);
      auto record =
          std::find_if(m.merges.begin() + static_cast<std::ptrdiff_t>(first_record), m.merges.end(),
                       [&](const UplinkMerge& u) { return u.requirement == p.requirement; });
      if (record == m.merges.end()) {  // a requirement of the mission, moved
        m.merges.push_back(record_of(package, p.requirement, "placed", p.location));
        record = m.merges.end() - 1;
      }
      record->rule = "placed";
      record->relation = p.relation;
      record->anchor = p.anchor;
    }
  }
}

void describe_merges(Mission& m) {
  auto selection = [&](const std::string& id) -> const fretish::SelectionRequirement* {
    for (const auto& s : m.selections)
      if (s.id == id) return &s;
    return nullptr;
  };
  for (auto& record : m.merges) {
    std::string message = record.requirement + ": ";
    std::string where;
    if (record.rule != "removed") {
      if (const auto* s = selection(record.requirement)) {
        record.adaptable = s->adaptable;
        const auto order = m.selections_for(s->adaptable);
        record.of = static_cast<int>(order.size());
        for (std::size_t i = 0; i < order.size(); ++i)
          if (order[i] == s) record.priority = static_cast<int>(i + 1);
        where = "priority " + std::to_string(record.priority) + " of " + std::to_string(record.of) +
                " in " + s->adaptable;
        if (!s->guard) where += "; the default, which always comes last";
        const auto* anchor = record.rule == "placed" ? selection(record.anchor) : nullptr;
        if (anchor != nullptr && anchor->adaptable != s->adaptable) {
          invalid(m.findings,
                  "uplink.json places '" + record.requirement + "' (adaptable node " +
                      s->adaptable + ") " + record.relation + " '" + record.anchor +
                      "' (adaptable node " + anchor->adaptable +
                      "): priority orders the requirements of one node",
                  record.location);
        }
      } else {
        where = "a mission property, no selection priority";
      }
    }
    if (record.rule == "appended")
      message += "new requirement, no placement in uplink.json: goes last before the default (" +
                 where + ")";
    else if (record.rule == "replaced")
      message += "replaces the requirement with the same id, in place (" + where + ")";
    else if (record.rule == "placed")
      message +=
          "placed " + record.relation + " " + record.anchor + " by uplink.json (" + where + ")";
    else
      message += "removed by uplink.json" +
                 (record.adaptable.empty() ? std::string() : " from " + record.adaptable);
    Finding f = make_finding("uplink-merge", message, record.location);
    f.adaptable = record.adaptable;
    f.requirements = {record.requirement};
    m.findings.push_back(std::move(f));
  }
}

}  // namespace uabt::load
