#pragma once
// Case files: YAML in, a validated CaseConfig out (docs/case-file.md describes every key).
//
// The schema below is declared once, as data: each key path with its type, default, allowed range or
// choices, units and meaning. The parser checks a case against it and the key table of the documentation
// is generated from it (schema_markdown()), so the two cannot disagree. Every mistake in a case is a
// CaseError whose message says where (file and line, or the --set that caused it), which key (full path,
// e.g. `boundaries.left.velocity`) and what is wrong with it.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "case_config.hpp"

namespace YAML {
class Node;
}

namespace chute {

// A mistake in a case file or in a --set override.
class CaseError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Read and validate a case file. `overrides` are "key.path=value" strings (the command line's --set),
// the value read as YAML (`domain.x.cells=64`, `boundaries.top.velocity=[1,0]`); they are applied, in
// order, before validation and may add keys the file does not give. The default name is the file stem.
CaseConfig load_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
// The same from YAML text (default name "case") or from an already parsed YAML document.
CaseConfig parse_case_text(const std::string& yaml_text, const std::vector<std::string>& overrides = {});
CaseConfig parse_case(const YAML::Node& root);

// The schema. In key paths, `<axis>` stands for x or y and `<side>` for left, right, bottom or top.
enum class KeyType {
    section,  // a mapping of further keys
    string,
    number,  // finite real
    integer,
    boolean,
    choice,           // one of `choices`
    vector2,          // [number, number]
    integer_vector2,  // [integer, integer]
    number_list,      // [number, ...]
    point_list,       // [[x, y], ...]
    number_or_auto,   // the word auto or a number
};

struct Bound {
    double value;
    bool inclusive;
};

struct CaseKey {
    std::string_view path;
    KeyType type;
    // Must be given whenever it applies (its section is given and the `when` condition holds).
    bool required = false;
    std::string_view default_value = {};      // YAML text of the default; empty: no default
    std::string_view default_doc = {};        // the default as documented, when it is not a plain value
    std::optional<Bound> min = {}, max = {};  // numbers, integers and the elements of vectors
    std::optional<double> also = {};          // one value allowed outside [min, max] (e.g. -1: no limit)
    std::vector<std::string_view> choices = {};
    // The key applies only when its sibling `when_key` (a choice) has one of `when_values`; given
    // otherwise it is an error.
    std::string_view when_key = {};
    std::vector<std::string_view> when_values = {};
    std::string_view units = {};
    std::string_view meaning = {};
};

const std::vector<CaseKey>& case_schema();

// The key table of docs/case-file.md (Markdown): key, type, default, allowed values, units, meaning.
std::string schema_markdown();

}  // namespace chute
