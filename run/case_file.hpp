#pragma once
// Case files: YAML in, a validated CaseConfig out (docs/case-file.md describes every key).
//
// The schema is declared once, as data, in sections that belong to the modules: each key path with its type,
// default, allowed range or choices, units and meaning (core/flow_keys.cpp, body/body_keys.cpp,
// ibm/ibm_keys.cpp, contact/contact_keys.cpp, rigidbody/rigidbody_keys.cpp, turbulence/turbulence_keys.cpp,
// and the run's own name and outputs in case_file.cpp). The generic reader (io/case_reader.hpp) checks a case
// against the assembled schema, each module reads its section, and the key table of the documentation is
// generated from it (schema_markdown()), so the two cannot disagree. Every mistake in a case is a CaseError
// whose message says where (file and line, or the --set that caused it), which key (full path, e.g.
// `boundaries.left.velocity`) and what is wrong with it.
#include <filesystem>
#include <string>
#include <vector>

#include "case_config.hpp"
#include "case_reader.hpp"

namespace chute {

// Read and validate a case file. `overrides` are "key.path=value" strings (the command line's --set),
// the value read as YAML (`domain.x.cells=64`, `boundaries.top.velocity=[1,0]`); they are applied, in
// order, before validation and may add keys the file does not give. The default name is the file stem.
CaseConfig load_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
// The same from YAML text (default name "case") or from an already parsed YAML document.
CaseConfig parse_case_text(const std::string& yaml_text, const std::vector<std::string>& overrides = {});
CaseConfig parse_case(const YAML::Node& root);

// The schema: every module's section, in the documented order. In key paths, `<axis>` stands for x or y,
// `<side>` for left, right, bottom or top, and `<body>` for a body's name.
const std::vector<CaseKey>& case_schema();

// The key table of docs/case-file.md (Markdown): key, type, default, allowed values, units, meaning.
std::string schema_markdown();

}  // namespace chute
