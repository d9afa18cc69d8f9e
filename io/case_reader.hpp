#pragma once
// The case-file reader: YAML in, checked and typed values out, against a schema given to it as data. It knows
// no module. Each module declares its own section of the schema (its keys, each with type, default, range or
// choices, units and meaning) and reads its own config through this reader (core/flow_config.hpp,
// body/body_config.hpp, ...); run/case_file.cpp assembles the sections into the case.
//
//   1. yaml-cpp parses the text; a syntax error becomes a CaseError with its line and column.
//   2. add_document() walks the mappings and files every key under its full path ("boundaries.left.velocity").
//      A key the schema does not know is an error, with the nearest known key suggested (optimal string
//      alignment distance) or the keys allowed there listed.
//   3. add_override() applies each --set: it replaces (or adds) that path and its sub-keys.
//   4. check_presence(): required keys are given; conditional keys (`when`) appear only where they apply and,
//      when required, are given there.
//   5. The typed reads (number(), choice(), vector2(), ...) check type, range and choices; an absent key takes
//      the schema's default, so the documented default is the one used. Checks that involve several keys are
//      the modules' (and, across modules, the assembly's), reported through fail().
// Every mistake is a CaseError whose message says where (file and line, or the --set that caused it), which
// key (full path) and what is wrong with it.
#include <yaml-cpp/yaml.h>

#include <array>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exact_text.hpp"  // numbers in messages: exact_text(v)

namespace chute {

// A mistake in a case file or in a --set override.
class CaseError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// ---- the schema, as data ----

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
    string_list,      // [text, ...]
    point_list,       // [[x, y], ...]
    number_or_auto,   // the word auto or a number
};

struct Bound {
    double value;
    bool inclusive;
};
constexpr Bound above(double v) { return {v, false}; }
constexpr Bound at_least(double v) { return {v, true}; }
constexpr Bound at_most(double v) { return {v, true}; }

// One key. Its path may hold placeholders (`<side>`) that stand for several names (see Placeholder).
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

// A path segment in angle brackets that stands for the names listed (`<side>`: left, right, bottom, top) or,
// with none listed, for any name of letters, digits, '_' and '-' starting with a letter: sections the case
// names itself (`<body>`).
struct Placeholder {
    std::string_view segment;
    std::vector<std::string_view> names = {};
};

// ---- the reader ----

class CaseReader {
public:
    // `keys` and `placeholders` are the whole schema; they must outlive the reader. `file` names the case in
    // messages (empty: text given directly, e.g. in tests).
    CaseReader(const std::vector<CaseKey>& keys, const std::vector<Placeholder>& placeholders, std::string file = {});

    // The keys of a YAML text (a syntax error is a CaseError naming the file, line and column), or of a parsed
    // document. An empty document gives no keys (the required ones are then missing).
    void add_text(const std::string& yaml_text);
    void add_document(const YAML::Node& root);
    // A --set "key.path=value": the value read as YAML replaces the key and everything under it, or adds it.
    void add_override(const std::string& text);
    // Required keys given, conditional keys only where they apply; in schema order, the first problem thrown.
    void check_presence() const;

    bool present(std::string_view path) const { return entries_.contains(path); }
    // Every concrete section present that matches a schema section pattern ("bodies.<body>"), in name order.
    std::vector<std::string> instances(std::string_view pattern) const;

    // Typed reads: the value given, or the schema's default; checked against the schema.
    double number(std::string_view path) const;
    long integer(std::string_view path) const;
    bool boolean(std::string_view path) const;
    std::string string(std::string_view path) const;
    std::string choice(std::string_view path) const;
    std::array<double, 2> vector2(std::string_view path) const;
    std::array<int, 2> integer_vector2(std::string_view path) const;
    std::vector<double> number_list(std::string_view path) const;
    std::vector<std::string> string_list(std::string_view path) const;
    std::vector<std::array<double, 2>> point_list(std::string_view path) const;
    std::optional<double> number_or_auto(std::string_view path) const;
    // A choice as an enum value: choice<ReboundLaw>("contact.law", {{"lumped", ReboundLaw::lumped}, ...}).
    // The table must cover the schema's choices (a missing one is a programming error, std::logic_error).
    template <class E>
    E choice(std::string_view path, std::initializer_list<std::pair<std::string_view, E>> table) const {
        const std::string value = choice(path);
        for (const auto& [name, e] : table)
            if (name == value) return e;
        throw std::logic_error("case_reader: choice '" + value + "' of " + std::string(path) + " has no enum value");
    }

    // A CaseError about `path`: "where: path: reason", where is the file and line of `node` (or of the key, or
    // of its nearest given section) or the --set that gave it.
    [[noreturn]] void fail(std::string_view path, const std::string& reason, const YAML::Node* node = nullptr) const;

    // "path[i]": the key path of a list's element, as messages name it.
    static std::string indexed(std::string_view path, std::size_t i);

private:
    struct Entry {
        YAML::Node node;
        YAML::Mark key_mark;  // where the key itself is written (null: made by a --set)
        std::string origin;   // the --set that gave it; empty: the file
    };

    // The schema: placeholders, matching, lookups and the hint after "unknown key".
    std::vector<std::string_view> expand(std::string_view segment) const;
    bool segment_matches(std::string_view pattern, std::string_view name) const;
    bool matches(std::string_view pattern, std::string_view path) const;
    const CaseKey* find_key(std::string_view path) const;
    std::vector<std::string> keys_under(std::string_view section) const;
    std::string unknown_key_hint(std::string_view path) const;
    const CaseKey& key(std::string_view path, KeyType type) const;

    void flatten(const YAML::Node& map, const std::string& section);
    void flatten_section(const YAML::Node& value, const std::string& path);
    std::string origin_of(std::string_view section) const;
    const Entry* nearest_entry(std::string_view path) const;
    std::string where(std::string_view path, const YAML::Node* node) const;

    YAML::Node node(std::string_view path, const CaseKey& k) const;
    void check_range(std::string_view path, const YAML::Node& n, double v, const CaseKey& k) const;
    double to_number(std::string_view path, const YAML::Node& n, const CaseKey& k) const;
    long to_integer(std::string_view path, const YAML::Node& n, const CaseKey& k) const;
    template <class T, class Item>
    std::array<T, 2> read_pair(std::string_view path, const YAML::Node& n, const std::string& what, Item item) const;

    const std::vector<CaseKey>& keys_;
    const std::vector<Placeholder>& placeholders_;
    std::string file_;
    std::map<std::string, Entry, std::less<>> entries_;  // full key path -> value, as given
};

// The key table of the documentation (Markdown): key, type, default, allowed values, units, meaning.
std::string markdown_table(const std::vector<CaseKey>& keys);

}  // namespace chute
