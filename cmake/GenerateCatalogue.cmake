# Turns checks/*.md into a C++ table: id, default severity, summary and the full text.
# Each file starts with a front-matter block:
#   ---
#   id: guard-overlap
#   severity: error
#   summary: one line
#   ---
file(GLOB docs ${CHECKS_DIR}/*.md)
list(FILTER docs EXCLUDE REGEX "/README\\.md$")
list(SORT docs)
set(body "")
foreach(doc IN LISTS docs)
  file(READ ${doc} text)
  string(REGEX MATCH "^---\n(.*)\n---\n" front "${text}")
  if(NOT front)
    message(FATAL_ERROR "${doc}: missing front matter")
  endif()
  string(REGEX MATCH "id: *([a-z0-9-]+)" _ "${CMAKE_MATCH_1}")
  set(id "${CMAKE_MATCH_1}")
  string(REGEX MATCH "severity: *(error|warning|note)" _ "${front}")
  set(sev "${CMAKE_MATCH_1}")
  string(REGEX MATCH "summary: *([^\n]*)" _ "${front}")
  set(summary "${CMAKE_MATCH_1}")
  string(REGEX MATCH "stage: *([a-z]+)" _ "${front}")
  set(stage "${CMAKE_MATCH_1}")
  get_filename_component(stem ${doc} NAME_WE)
  if(NOT id STREQUAL stem)
    message(FATAL_ERROR "${doc}: id '${id}' must equal the file name")
  endif()
  if(NOT sev OR NOT summary OR NOT stage)
    message(FATAL_ERROR "${doc}: front matter needs id, severity, stage and summary")
  endif()
  string(LENGTH "${front}" front_len)
  string(SUBSTRING "${text}" ${front_len} -1 doc_body)
  string(APPEND body "    {\"${id}\", \"${sev}\", \"${stage}\", R\"uabtdoc(${summary})uabtdoc\", R\"uabtdoc(${doc_body})uabtdoc\"},\n")
endforeach()
file(WRITE ${OUT}.tmp "// Generated from checks/*.md by cmake/GenerateCatalogue.cmake. Do not edit.\n#include \"base/catalogue.hpp\"\nnamespace uabt {\nconst std::vector<CheckInfo>& check_catalogue() {\n  static const std::vector<CheckInfo> table = {\n${body}  };\n  return table;\n}\n}  // namespace uabt\n")
file(RENAME ${OUT}.tmp ${OUT})
