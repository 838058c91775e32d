// world.json → WorldModel, with errors that point into the file.
#include "prove/world_model.hpp"

#include <cctype>
#include <nlohmann/json.hpp>

#include "base/files.hpp"
#include "base/json_input.hpp"
#include "fretish/parse.hpp"
#include "runtime/script/program.hpp"

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
    std::size_t from = 0;
    for (std::string_view k : keys) {
      const std::size_t found = text_.find("\"" + std::string(k) + "\"", from);
      if (found == std::string_view::npos) break;
      from = found;
    }
    const auto [line, column] = position(text_, from);
    return {file_, line, column};
  }
  [[noreturn]] void fail(const SourceLocation& where, const std::string& message) const {
    throw WorldError(where, message);
  }

 private:
  std::string_view text_;
  std::string file_;
};

std::int64_t tick_count(const Json& j, const Locator& loc, const SourceLocation& where) {
  if (!j.is_number_integer() || j.get<std::int64_t>() < 1)
    loc.fail(where, "ticks must be a whole number of ticks >= 1, not " + j.dump());
  return j.get<std::int64_t>();
}

ActionContract contract(const std::string& name, const Json& j, const Locator& loc) {
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
      try {
        runtime::script::Program::parse(code);
      } catch (const std::exception& e) {
        loc.fail(at, key + " of '" + name + "': " + e.what() + " in `" + code + "`");
      }
      (key == "on_success" ? c.on_success : c.on_failure) = code;
    } else {
      loc.fail(at, "unknown key '" + key + "' (expected: ticks, results, on_success, on_failure)");
    }
  }
  return c;
}

}  // namespace

const ActionContract* WorldModel::find(std::string_view qualified, std::string_view plain) const {
  auto it = actions.find(qualified);
  if (it == actions.end()) it = actions.find(plain);
  return it == actions.end() ? nullptr : &it->second;
}

WorldModel parse_world(std::string_view text, const std::string& file) {
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
      for (const Finding& f : findings)
        if (f.severity == Severity::error) loc.fail(f.location, "initial: " + f.message);
    } else if (key == "actions") {
      if (!value.is_object()) loc.fail(at, "actions must be an object");
      for (const auto& [name, spec] : value.items())
        w.actions.emplace(name, contract(name, spec, loc));
    } else if (key != "description") {
      loc.fail(at, "unknown key '" + key + "' (expected: initial, actions, description)");
    }
  }
  return w;
}

WorldModel load_world(const std::filesystem::path& path, const std::string& display) {
  std::string error;
  const auto text = read_text_file(path, error);
  if (!text) throw WorldError({display, 0, 0}, error);
  return parse_world(*text, display);
}

std::vector<std::string> assigned_names(std::string_view script) {
  std::vector<std::string> out;
  std::size_t i = 0;
  auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '@';
  };
  while (i < script.size()) {
    // At a statement start: skip blanks, read a name, look at the operator after it.
    while (i < script.size() && std::isspace(static_cast<unsigned char>(script[i]))) ++i;
    std::size_t j = i;
    while (j < script.size() && is_name_char(script[j])) ++j;
    std::string name(script.substr(i, j - i));
    std::size_t k = j;
    while (k < script.size() && std::isspace(static_cast<unsigned char>(script[k]))) ++k;
    const std::string_view rest = script.substr(k);
    const bool assigns =
        !name.empty() &&
        ((rest.size() >= 1 && rest[0] == '=' && (rest.size() < 2 || rest[1] != '=')) ||
         rest.rfind(":=", 0) == 0 || rest.rfind("+=", 0) == 0 || rest.rfind("-=", 0) == 0 ||
         rest.rfind("*=", 0) == 0 || rest.rfind("/=", 0) == 0);
    if (assigns) {
      if (name.front() == '@') name.erase(0, 1);
      out.push_back(name);
    }
    const std::size_t semi = script.find(';', k);
    if (semi == std::string_view::npos) break;
    i = semi + 1;
  }
  return out;
}

}  // namespace uabt::prove
