#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "bt/xml_io.hpp"
#include "compile/compile.hpp"
#include "conform/conform.hpp"
#include "load/mission.hpp"

namespace uabt::testing {

inline load::Mission load_or_fail(const std::filesystem::path& dir) {
  std::string error;
  auto m = load::load_mission(dir, {}, error);
  if (!m) ADD_FAILURE() << dir << ": " << error;
  return m ? std::move(*m) : load::Mission{};
}

inline bt::Document compile_or_fail(const load::Mission& m, compile::SelectionStyle style,
                                    int bt_format = 4) {
  compile::Options options;
  options.selection = style;
  options.selection_forced = true;
  options.bt_format = bt_format;
  compile::Result r = compile::compile_mission(m, options);
  EXPECT_TRUE(r.ok) << m.name << ": compilation failed";
  return std::move(r.document);
}

inline bt::Document parse_or_fail(const std::string& xml,
                                  const std::string& file = "compiled.xml") {
  std::vector<Finding> findings;
  auto doc = bt::parse_document(xml, file, findings);
  if (!doc) ADD_FAILURE() << "cannot parse:\n" << xml;
  return doc ? std::move(*doc) : bt::Document{};
}

inline std::string describe(const std::vector<Finding>& findings) {
  std::string out;
  for (const auto& f : findings)
    out += f.location.file + ":" + std::to_string(f.location.line) + ":" +
           std::to_string(f.location.column) + ": " + severity_name(f.severity) + ": " + f.message +
           " [" + f.check + "] {" + f.node_path + "}\n";
  return out.empty() ? "(no findings)\n" : out;
}

inline std::vector<const Finding*> with_check(const std::vector<Finding>& findings,
                                              const std::string& check) {
  std::vector<const Finding*> out;
  for (const auto& f : findings)
    if (f.check == check) out.push_back(&f);
  return out;
}

inline bool has_check(const std::vector<Finding>& findings, const std::string& check) {
  return !with_check(findings, check).empty();
}

}  // namespace uabt::testing
