// world.json → WorldModel, with errors that point into the file.
#include "prove/world_model.hpp"
#include "base/diagnostics.hpp"

#include <cctype>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "base/files.hpp"
#include "base/json_input.hpp"
#include "fretish/parse.hpp"
#include "load/mission.hpp"
#include "runtime/scenario_check.hpp"
#include "runtime/script/program.hpp"
#include "verify/division.hpp"
#include "verify/script_reading.hpp"

namespace uabt::prove {

namespace {

using Json = nlohmann::ordered_json;

std::pair<int, int> position(std::string_view text, std::size_t offset) {
  int line = 1;
  std::size_t start = 0;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i)
    if (text[i] == '\n') {
      ++line;
      start = i + 1;
    }
  return {line, static_cast<int>(offset - start) + 1};
}

// Where a member's key stands: the first `"key"` after the parent's key (good enough for
// the small, flat files world.json is).
class Locator {
 public:
  Locator(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}
  SourceLocation at(std::initializer_list<std::string_view> keys) const {
    return at_offset(offset_of(keys));
  }
  std::size_t offset_of(std::initializer_list<std::string_view> keys) const {
    std::size_t from = 0;
    for (std::string_view k : keys) {
      const std::size_t found = text_.find("\"" + std::string(k) + "\"", from);
      if (found == std::string_view::npos) break;
      from = found;
    }
    return from;
  }
  SourceLocation at_offset(std::size_t offset) const {
    const auto [line, column] = position(text_, offset);
    return {file_, line, column};
  }
  // Where character `column` (1-based) of the string value of the member at `key_offset`
  // stands in the file, escapes counted as written.
  SourceLocation in_value(std::size_t key_offset, std::size_t column) const {
    const std::size_t colon = text_.find(':', key_offset);
    std::size_t i = colon == std::string_view::npos ? key_offset : text_.find('"', colon);
    if (i == std::string_view::npos) return at_offset(key_offset);
    ++i;
    for (std::size_t c = 1; c < column && i < text_.size() && text_[i] != '"'; ++c)
      i += text_[i] != '\\' ? 1 : (i + 1 < text_.size() && text_[i + 1] == 'u' ? 6 : 2);
    return at_offset(i);
  }
  // Where the value of the member whose key starts at `key_offset` starts.
  SourceLocation value_at(std::size_t key_offset) const {
    std::size_t i = text_.find(':', key_offset);
    if (i == std::string_view::npos) return at_offset(key_offset);
    ++i;
    while (i < text_.size() && std::isspace(static_cast<unsigned char>(text_[i]))) ++i;
    return at_offset(i);
  }
  std::string_view text() const { return text_; }
  [[noreturn]] void fail(const SourceLocation& where, const std::string& message,
                         const std::string& check = "load-file") const {
    throw WorldError(where, message, check);
  }

 private:
  std::string_view text_;
  std::string file_;
};

// Where the key `"key"` stands after `from` (the member of the object that starts there).
std::size_t text_find_key(const Locator& loc, std::size_t from, const std::string& key) {
  const std::size_t found = loc.text().find("\"" + key + "\"", from);
  return found == std::string_view::npos ? from : found;
}

std::int64_t tick_count(const Json& j, const Locator& loc, const SourceLocation& where) {
  if (!j.is_number_integer() || j.get<std::int64_t>() < 1)
    loc.fail(where, "ticks must be a whole number of ticks >= 1, not " + j.dump());
  return j.get<std::int64_t>();
}

// The names a world.json may use for one mission.
struct Vocabulary {
  runtime::ScenarioVocabulary scenario;
  const fretish::Domain* domain = nullptr;
  std::set<std::string> writable;  // domain variables and the mission's conditions
};

// Every division of an effect whose divisor can be zero in the domain: an error with the state.
void check_divisions(const runtime::script::Program& program, const std::string& action,
                     const std::string& key, std::size_t key_offset, const Vocabulary& v,
                     const Locator& loc) {
  using runtime::script::Op;
  for (const auto& e : program.nodes()) {
    if (e.op != Op::div && e.op != Op::div_assign) continue;
    const fretish::ExprPtr divisor =
        verify::read_script_expression(program.script(), e.b, *v.domain).expr;
    if (!divisor) continue;
    const auto state = verify::zero_divisor_state(*v.domain, divisor, {});
    if (!state) continue;
    const std::string shown = fretish::to_fretish(*divisor);
    loc.fail(
        loc.in_value(key_offset, e.column),
        key + " of '" + action + "' divides by " + shown +
            (divisor->kind == fretish::ExprKind::number
                 ? ""
                 : ", which is zero in a state the domain allows (" + format_state(*state) + ")") +
            ": BT.CPP's script then fails or gives infinity",
        "guard-division-by-zero");
  }
}

// An effect's assignments against the mission: the name is writable, a constant value fits.
void check_effect(const runtime::script::Program& program, const std::string& action,
                  const std::string& key, std::size_t key_offset, const Vocabulary& v,
                  const Locator& loc) {
  using runtime::script::Op;
  const auto& nodes = program.nodes();
  for (const std::uint32_t s : program.statements()) {
    const auto& e = nodes[s];
    if (!bt::script::is_assignment(e.op)) continue;
    const auto& target = nodes[e.a];
    if (target.op != Op::name) continue;
    const std::string name = bt::script::entry_key(target.name);
    if (!v.writable.contains(name))
      loc.fail(loc.in_value(key_offset, target.column),
               key + " of '" + action + "' writes '" + name +
                   "', which is neither a variable of the domain nor a condition of the mission" +
                   runtime::did_you_mean_hint(name, v.writable));
    if (e.op != Op::assign && e.op != Op::assign_create) continue;
    const auto& value = nodes[e.b];
    std::optional<runtime::ScriptValue> constant;
    if (value.op == Op::literal) constant = value.literal;
    if (value.op == Op::negate && nodes[value.a].op == Op::literal) {
      const auto& l = nodes[value.a].literal;
      if (l.kind == runtime::ScriptValue::Kind::integer && l.integer != INT64_MIN)
        constant = runtime::ScriptValue::of_int(-l.integer);
      if (l.kind == runtime::ScriptValue::Kind::real)
        constant = runtime::ScriptValue::of_real(-l.real);
    }
    const fretish::Variable* var = v.domain->find(name);
    if (!constant || var == nullptr || !var->declared) continue;
    const std::string why = runtime::misfit_message(name, *constant, *var);
    if (!why.empty())
      loc.fail(loc.in_value(key_offset, value.column), key + " of '" + action + "': " + why);
  }
}

ActionContract contract(const std::string& name, const Json& j, const Locator& loc,
                        const Vocabulary* vocabulary) {
  const SourceLocation where = loc.at({"actions", name});
  if (!j.is_object()) loc.fail(where, "action '" + name + "' must be an object");
  ActionContract c;
  c.name = name;
  c.location = where;
  c.results = {runtime::NodeStatus::success, runtime::NodeStatus::failure};
  for (const auto& [key, value] : j.items()) {
    const SourceLocation at = loc.at({"actions", name, key});
    if (key == "ticks") {
      if (value.is_array()) {
        if (value.size() != 2) loc.fail(at, "ticks must be a number or [min, max]");
        c.min_ticks = tick_count(value[0], loc, at);
        c.max_ticks = tick_count(value[1], loc, at);
        if (c.min_ticks > c.max_ticks)
          loc.fail(at, "ticks [" + std::to_string(c.min_ticks) + ", " +
                           std::to_string(c.max_ticks) + "]: min is above max");
      } else {
        c.min_ticks = c.max_ticks = tick_count(value, loc, at);
      }
    } else if (key == "results") {
      if (!value.is_array() || value.empty())
        loc.fail(at, "results must be a non-empty array of \"success\"/\"failure\"");
      c.results.clear();
      for (const Json& r : value) {
        if (r == "success") {
          c.results.push_back(runtime::NodeStatus::success);
        } else if (r == "failure") {
          c.results.push_back(runtime::NodeStatus::failure);
        } else {
          loc.fail(at, "a result is \"success\" or \"failure\", not " + r.dump());
        }
      }
    } else if (key == "on_success" || key == "on_failure") {
      if (!value.is_string()) loc.fail(at, key + " must be a BT.CPP script (a string)");
      const std::string code = value.get<std::string>();
      std::optional<runtime::script::Program> program;
      try {
        program = runtime::script::Program::parse(code);
      } catch (const std::exception& e) {
        loc.fail(at, key + " of '" + name + "': " + e.what() + " in `" + code + "`");
      }
      if (vocabulary != nullptr) {
        const std::size_t offset = loc.offset_of({"actions", name, key});
        check_effect(*program, name, key, offset, *vocabulary, loc);
        check_divisions(*program, name, key, offset, *vocabulary, loc);
      }
      (key == "on_success" ? c.on_success : c.on_failure) = code;
    } else if (key == "outputs") {
      if (!value.is_object())
        loc.fail(at, "outputs must be an object: output port -> the value the action writes");
      const std::size_t outputs_offset = loc.offset_of({"actions", name, key});
      for (const auto& [port, v] : value.items()) {
        const std::size_t port_offset = text_find_key(loc, outputs_offset, port);
        runtime::ScriptValue written;
        if (v.is_boolean()) {
          written = runtime::ScriptValue::of_bool(v.get<bool>());
        } else if (v.is_number_integer() &&
                   !(v.is_number_unsigned() && v.get<std::uint64_t>() > INT64_MAX)) {
          written = runtime::ScriptValue::of_int(v.get<std::int64_t>());
        } else if (v.is_number_float()) {
          written = runtime::ScriptValue::of_real(v.get<double>());
        } else if (v.is_string()) {
          written = runtime::ScriptValue::of_string(v.get<std::string>());
        } else {
          loc.fail(loc.value_at(port_offset), "outputs of '" + name + "': the value of '" + port +
                                                  "' must be a boolean, a number or a string, "
                                                  "not " +
                                                  v.dump());
        }
        // Typed as a scenario's output is, by the port's type: `2` for a double port is 2.0.
        if (vocabulary != nullptr)
          runtime::type_number(written, vocabulary->scenario.output_type(name, port));
        if (vocabulary != nullptr && vocabulary->scenario.is_leaf(name)) {
          bool at_value = false;
          const std::string why = vocabulary->scenario.output_misfit(name, port, written, at_value);
          if (!why.empty())
            loc.fail(at_value ? loc.value_at(port_offset) : loc.at_offset(port_offset),
                     "outputs of '" + name + "': " + why);
        }
        c.outputs[port] = written;
      }
    } else {
      loc.fail(at, "unknown key '" + key +
                       "' (expected: ticks, results, on_success, on_failure, outputs)");
    }
  }
  return c;
}

// An entry for an action that no tree runs describes nothing on board. When its name is close
// to a leaf that has no entry, it may be a typo: the real action would then be modelled as
// doing anything and writing nothing, and what the entry's effects would change stays put, so
// a guarantee about it could be proved vacuously. Names one digit apart are common (Drive1,
// Drive2), so the name alone cannot decide it: a warning that says which leaf is undescribed.
// One world.json also describes the actions that uplinks may add.
void check_action_names(WorldModel& w, const Vocabulary& vocabulary) {
  std::set<std::string> undescribed;
  for (const std::string& leaf : vocabulary.scenario.leaves)
    if (!w.actions.contains(leaf) && vocabulary.domain->find(leaf) == nullptr)
      undescribed.insert(leaf);
  for (const auto& [name, c] : w.actions) {
    if (vocabulary.scenario.is_leaf(name)) continue;
    const std::string base = name.substr(0, name.find('('));
    Finding f = make_finding("world-unknown-action",
                             "no tree of the mission runs '" + name +
                                 "': its entry takes effect only once an uplink adds it",
                             c.location);
    f.severity = Severity::warning;
    if (const std::string hint = runtime::did_you_mean_hint(base, undescribed); !hint.empty())
      f.notes.push_back(hint.substr(hint.find('(') + 1, hint.rfind(')') - hint.find('(') - 1) +
                        " That leaf has no entry: as written, it may do anything and writes "
                        "nothing in the proof");
    w.warnings.push_back(std::move(f));
  }
}

}  // namespace

const ActionContract* WorldModel::find(std::string_view qualified, std::string_view plain) const {
  auto it = actions.find(qualified);
  if (it == actions.end()) it = actions.find(plain);
  return it == actions.end() ? nullptr : &it->second;
}

WorldModel parse_world(std::string_view text, const std::string& file,
                       const load::Mission* mission) {
  std::optional<Vocabulary> vocabulary;
  if (mission != nullptr) {
    vocabulary.emplace();
    vocabulary->scenario.add(*mission);
    vocabulary->domain = &mission->domain;
    for (const fretish::Variable& var : mission->domain.variables)
      vocabulary->writable.insert(var.name);
    for (const std::string& leaf : vocabulary->scenario.leaves)
      if (mission->domain.find(leaf) == nullptr) vocabulary->writable.insert(leaf);
  }
  JsonInputError error;
  std::optional<Json> parsed = parse_json_input<Json>(text, error);
  if (!parsed) throw WorldError({file, error.line, error.column}, error.message);
  const Json root = std::move(*parsed);
  const Locator loc(text, file);
  WorldModel w;
  w.file = file;
  if (!root.is_object()) loc.fail({file, 1, 1}, "world.json must be a JSON object");
  for (const auto& [key, value] : root.items()) {
    const SourceLocation at = loc.at({key});
    if (key == "initial") {
      if (!value.is_string()) loc.fail(at, "initial must be a FRETISH expression (a string)");
      std::vector<Finding> findings;
      // The expression starts one past the opening quote of its value.
      const std::size_t quote = text.find('"', text.find(':', text.find("\"initial\"")));
      const auto [line, column] = position(text, quote + 1);
      w.initial = fretish::parse_expression(value.get<std::string>(),
                                            fretish::TextOrigin{file, line, column}, findings);
      for (const Finding& f : findings) {
        if (f.severity != Severity::error) continue;
        // The parser counts in the decoded string: "\n" and "\u0041" are written otherwise.
        loc.fail(loc.at_offset(json_string_source_offset(text, quote, line, column, f.location.line,
                                                         f.location.column)),
                 "initial: " + f.message);
      }
    } else if (key == "actions") {
      if (!value.is_object()) loc.fail(at, "actions must be an object");
      for (const auto& [name, spec] : value.items())
        w.actions.emplace(name, contract(name, spec, loc, vocabulary ? &*vocabulary : nullptr));
    } else if (key != "description") {
      loc.fail(at, "unknown key '" + key + "' (expected: initial, actions, description)");
    }
  }
  if (vocabulary) check_action_names(w, *vocabulary);
  return w;
}

WorldModel load_world(const std::filesystem::path& path, const std::string& display,
                      const load::Mission* mission) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw WorldError({display, 0, 0}, "is a directory, not a file: the world model is a JSON file");
  if (mission != nullptr && !lies_inside(path, mission->dir))
    throw WorldError({display, 0, 0}, outside_folder_error("the mission folder"));
  std::string error;
  const auto text = read_text_file(path, error);
  if (!text) throw WorldError({display, 0, 0}, error);
  return parse_world(*text, display, mission);
}

WorldModel mission_world(const load::Mission& mission) {
  std::error_code ec;
  if (!std::filesystem::exists(mission.dir / "world.json", ec)) return {};
  return load_world(mission.dir / "world.json", "world.json", &mission);
}

std::vector<std::string> assigned_names(std::string_view script) {
  try {
    return bt::script::Script::parse(script).assigned();
  } catch (const bt::script::ScriptError&) {
    return {};
  }
}

}  // namespace uabt::prove
