// The case-file reader (case_reader.hpp): YAML flattened into a table of key paths, checked against the schema
// it is given.
#include "case_reader.hpp"

#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <sstream>

namespace chute {

namespace {

// ---- key paths -------------------------------------------------------------------------------------

// A name the case gives a section itself: letters, digits, '_' and '-', starting with a letter.
bool is_section_name(std::string_view s) {
    if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
    return std::all_of(s.begin(), s.end(),
                       [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-'; });
}

std::vector<std::string_view> split(std::string_view path) {
    std::vector<std::string_view> parts;
    if (path.empty()) return parts;
    for (std::size_t begin = 0;;) {
        const std::size_t dot = path.find('.', begin);
        parts.push_back(path.substr(begin, dot == std::string_view::npos ? dot : dot - begin));
        if (dot == std::string_view::npos) return parts;
        begin = dot + 1;
    }
}

std::string_view parent_of(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    return dot == std::string_view::npos ? std::string_view{} : path.substr(0, dot);
}

std::string_view leaf_of(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    return dot == std::string_view::npos ? path : path.substr(dot + 1);
}

std::string join(std::string_view parent, std::string_view leaf) {
    return parent.empty() ? std::string(leaf) : std::string(parent) + "." + std::string(leaf);
}

// ---- text helpers ----------------------------------------------------------------------------------

std::string list(const std::vector<std::string_view>& items, std::string_view last_sep = ", ") {
    std::string s;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) s += (i + 1 == items.size()) ? last_sep : ", ";
        s += items[i];
    }
    return s;
}

// The gist of a key's meaning, for a hint: its text up to the first '.', ';' or ':'.
std::string gist(std::string_view text) {
    std::size_t stop = text.size();
    for (std::string_view mark : {". ", "; ", ": "}) stop = std::min(stop, text.find(mark));
    std::string s(text.substr(0, stop));
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

// Optimal string alignment distance: edits, with a swap of neighbours counting as one.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The candidate nearest to `word`, if it is near enough to be a likely typo.
std::optional<std::string> nearest(std::string_view word, const std::vector<std::string>& candidates) {
    const std::size_t limit = std::clamp<std::size_t>(word.size() / 3, 1, 3);
    std::optional<std::string> best;
    std::size_t best_distance = limit + 1;
    for (const std::string& c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_distance) best = c, best_distance = d;
    }
    return best;
}

std::string describe(const YAML::Node& n) {
    switch (n.Type()) {
        case YAML::NodeType::Scalar:
            return "'" + n.Scalar() + "'";
        case YAML::NodeType::Sequence:
            return "a list";
        case YAML::NodeType::Map:
            return "a mapping";
        default:
            return "nothing (empty value)";
    }
}

std::string range_text(const CaseKey& k, bool in_sentence) {
    std::string r;
    if (k.min && k.max)
        r = std::string(in_sentence ? "in " : "") + (k.min->inclusive ? "[" : "(") + exact_text(k.min->value) + ", " +
            exact_text(k.max->value) + (k.max->inclusive ? "]" : ")");
    else if (k.min)
        r = (k.min->inclusive ? ">= " : "> ") + exact_text(k.min->value);
    else if (k.max)
        r = (k.max->inclusive ? "<= " : "< ") + exact_text(k.max->value);
    if (k.also) r = exact_text(*k.also) + " or " + r;
    return r;
}

std::string trim(const std::string& s) {
    const std::size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string{} : s.substr(b, e - b + 1);
}

// Where the first node of a document is, if the document holds one (an empty document does not count).
class DocumentContent : public YAML::EventHandler {
public:
    YAML::Mark first = YAML::Mark::null_mark();

    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { see(m); }
    void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t, const std::string&) override { see(m); }
    void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
        see(m);
    }
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
        see(m);
    }
    void OnMapEnd() override {}

private:
    void see(const YAML::Mark& m) {
        if (first.is_null()) first = m;
    }
};

// The start of a second YAML document with something in it (after a '---' line), or a null mark. YAML::Load
// reads the first document only and drops the rest without a word. (Not YAML::LoadAll: on some broken texts,
// a lone ',' for one, yaml-cpp 0.7 yields empty documents without end, so the documents are capped here.)
YAML::Mark start_of_second_document(const std::string& text) {
    std::istringstream in(text);
    YAML::Parser parser(in);
    DocumentContent first;
    if (!parser.HandleNextDocument(first)) return YAML::Mark::null_mark();
    for (int document = 1; document < 64; ++document) {
        DocumentContent next;
        if (!parser.HandleNextDocument(next)) break;
        if (!next.first.is_null()) return next.first;
    }
    return YAML::Mark::null_mark();
}

}  // namespace

std::string CaseReader::indexed(std::string_view path, std::size_t i) {
    return std::string(path) + "[" + std::to_string(i) + "]";
}

CaseReader::CaseReader(const std::vector<CaseKey>& keys, const std::vector<Placeholder>& placeholders, std::string file)
    : keys_(keys), placeholders_(placeholders), file_(std::move(file)) {}

// ---- the schema --------------------------------------------------------------------------------------

// The names a path segment stands for: a placeholder's values, or itself. (A placeholder with no names
// listed stands for any section name and is matched by segment_matches.)
std::vector<std::string_view> CaseReader::expand(std::string_view segment) const {
    for (const Placeholder& p : placeholders_)
        if (p.segment == segment && !p.names.empty()) return p.names;
    return {segment};
}

// Does the concrete path ("boundaries.left.type") match the schema pattern ("boundaries.<side>.type")?
bool CaseReader::segment_matches(std::string_view pattern, std::string_view name) const {
    for (const Placeholder& p : placeholders_)
        if (p.segment == pattern && p.names.empty()) return is_section_name(name);
    const auto names = expand(pattern);
    return std::find(names.begin(), names.end(), name) != names.end();
}

bool CaseReader::matches(std::string_view pattern, std::string_view path) const {
    const auto a = split(pattern), b = split(path);
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!segment_matches(a[i], b[i])) return false;
    return true;
}

const CaseKey* CaseReader::find_key(std::string_view path) const {
    for (const CaseKey& key : keys_)
        if (matches(key.path, path)) return &key;
    return nullptr;
}

// The key names the schema allows directly under a concrete section ("" for the top level).
std::vector<std::string> CaseReader::keys_under(std::string_view section) const {
    std::vector<std::string> names;
    for (const CaseKey& key : keys_)
        if (matches(parent_of(key.path), section))
            for (std::string_view name : expand(leaf_of(key.path))) names.emplace_back(name);
    return names;
}

// The hint after "unknown key": the likely intended key, or the keys allowed there.
std::string CaseReader::unknown_key_hint(std::string_view path) const {
    const std::string_view section = parent_of(path), name = leaf_of(path);
    const std::vector<std::string> siblings = keys_under(section);
    if (auto best = nearest(name, siblings)) return "; did you mean '" + join(section, *best) + "'?";
    for (const CaseKey& key : keys_)
        if (leaf_of(key.path) == name) return "; did you mean '" + std::string(key.path) + "'?";
    std::string hint = section.empty() ? "; top-level keys: " : "; keys in " + std::string(section) + ": ";
    for (std::size_t i = 0; i < siblings.size(); ++i) hint += (i ? ", " : "") + siblings[i];
    return hint;
}

const CaseKey& CaseReader::key(std::string_view path, KeyType type) const {
    const CaseKey* k = find_key(path);
    if (!k || k->type != type)
        throw std::logic_error("case_reader: no schema key '" + std::string(path) + "' of the type read");
    return *k;
}

// ---- the case's keys, as given -----------------------------------------------------------------------

void CaseReader::add_text(const std::string& yaml_text) {
    YAML::Node root;
    YAML::Mark second_document = YAML::Mark::null_mark();
    try {
        root = YAML::Load(yaml_text);
        second_document = start_of_second_document(yaml_text);
    } catch (const YAML::Exception& e) {
        std::string where = file_.empty() ? "" : file_ + ", ";
        if (!e.mark.is_null())
            where += "line " + std::to_string(e.mark.line + 1) + ", column " + std::to_string(e.mark.column + 1);
        throw CaseError(where + ": YAML syntax error: " + e.msg);
    }
    if (!second_document.is_null())
        throw CaseError((file_.empty() ? "" : file_ + ", ") + "line " + std::to_string(second_document.line + 1) +
                        ": a case is one YAML document, but a '---' line starts another one here");
    add_document(root);
}

void CaseReader::add_document(const YAML::Node& root) {
    if (!root.IsDefined() || root.IsNull()) return;  // an empty file: the required keys are missing
    if (!root.IsMap()) fail("", "a case is a mapping of keys (key: value lines), got " + describe(root), &root);
    flatten(root, "");
}

void CaseReader::add_override(const std::string& text) {
    const std::string where = "--set " + text;
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) throw CaseError(where + ": expected key.path=value");
    const std::string path = trim(text.substr(0, eq));
    if (path.empty()) throw CaseError(where + ": no key path before '='");
    // Every step of the path must be a known key, and all but the last a section.
    const auto steps = split(path);
    std::string prefix;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        prefix = join(prefix, steps[i]);
        const CaseKey* key = find_key(prefix);
        if (!key) throw CaseError(where + ": " + prefix + ": unknown key" + unknown_key_hint(prefix));
        if (i + 1 < steps.size() && key->type != KeyType::section)
            throw CaseError(where + ": " + prefix + ": takes a value, it has no sub-keys");
        if (i + 1 < steps.size() && !entries_.contains(prefix))
            entries_[prefix] = {YAML::Node(YAML::NodeType::Null), YAML::Mark::null_mark(), text};
    }
    YAML::Node value;
    try {
        value = YAML::Load(text.substr(eq + 1));
    } catch (const YAML::Exception& e) {
        throw CaseError(where + ": " + path + ": YAML syntax error in the value: " + e.msg);
    }
    // The new value replaces the old one and everything under it.
    std::erase_if(entries_,
                  [&](const auto& entry) { return entry.first == path || entry.first.starts_with(path + "."); });
    entries_[path] = {value, YAML::Mark::null_mark(), text};
    if (find_key(path)->type == KeyType::section) flatten_section(value, path);
}

void CaseReader::flatten(const YAML::Node& map, const std::string& section) {
    for (const auto& item : map) {
        const YAML::Node& key = item.first;
        if (!key.IsScalar()) fail(section, "keys must be plain names, got " + describe(key), &key);
        const std::string path = join(section, key.Scalar());
        if (!find_key(path)) fail(path, "unknown key" + unknown_key_hint(path), &key);
        if (const auto old = entries_.find(path); old != entries_.end()) {
            const YAML::Mark m = old->second.key_mark;
            fail(path, "given twice" + (m.is_null() ? "" : " (first on line " + std::to_string(m.line + 1) + ")"),
                 &key);
        }
        const std::string origin = origin_of(section);
        entries_[path] = {item.second, key.Mark(), origin};
        if (find_key(path)->type == KeyType::section) flatten_section(item.second, path);
    }
}

void CaseReader::flatten_section(const YAML::Node& value, const std::string& path) {
    if (value.IsMap())
        flatten(value, path);
    else if (!value.IsNull())
        fail(path, "expected a mapping of keys (key: value), got " + describe(value), &value);
}

std::string CaseReader::origin_of(std::string_view section) const {
    const auto it = entries_.find(section);
    return it == entries_.end() ? std::string{} : it->second.origin;
}

// The entry at `path` or, if that is absent, at its nearest ancestor.
const CaseReader::Entry* CaseReader::nearest_entry(std::string_view path) const {
    std::string_view p = path.substr(0, path.find('['));
    for (; !p.empty(); p = parent_of(p))
        if (const auto it = entries_.find(p); it != entries_.end()) return &it->second;
    return nullptr;
}

// "file, line N", or "--set key=value", for an error about `path`: the line of its value `node` if
// given, else of the key itself or, for a missing key, of its section's key.
std::string CaseReader::where(std::string_view path, const YAML::Node* node) const {
    const Entry* e = nearest_entry(path);
    if (e && !e->origin.empty()) return "--set " + e->origin;
    YAML::Mark mark = YAML::Mark::null_mark();
    if (node && node->IsDefined())
        mark = node->Mark();
    else if (e)
        mark = e->key_mark;
    std::string s = file_;
    if (!mark.is_null()) s += (s.empty() ? "" : ", ") + std::string("line ") + std::to_string(mark.line + 1);
    return s;
}

void CaseReader::fail(std::string_view path, const std::string& reason, const YAML::Node* node) const {
    const std::string w = where(path, node);
    throw CaseError((w.empty() ? "" : w + ": ") + (path.empty() ? "" : std::string(path) + ": ") + reason);
}

std::vector<std::string> CaseReader::instances(std::string_view pattern) const {
    if (pattern.empty()) return {""};
    std::vector<std::string> found;
    for (const auto& [path, entry] : entries_)
        if (matches(pattern, path)) found.push_back(path);
    return found;
}

void CaseReader::check_presence() const {
    for (const CaseKey& k : keys_) {
        for (const std::string& section : instances(parent_of(k.path))) {
            for (std::string_view name : expand(leaf_of(k.path))) {
                const std::string path = join(section, name);
                std::string condition;  // the value of the `when` key, if the key does not apply
                bool applies = true;
                if (!k.when_key.empty()) {
                    condition = choice(join(section, k.when_key));
                    applies = std::find(k.when_values.begin(), k.when_values.end(), condition) != k.when_values.end();
                }
                if (present(path) && !applies)
                    fail(path, "not used when " + std::string(k.when_key) + " is '" + condition + "' (only with " +
                                   std::string(k.when_key) + ": " + list(k.when_values, " or ") + ")");
                if (!present(path) && applies && k.required)
                    fail(path, "missing required key (" +
                                   (k.type == KeyType::choice ? "one of " + list(k.choices) : gist(k.meaning)) +
                                   (k.when_key.empty()
                                        ? ""
                                        : "; needed when " + std::string(k.when_key) + " is '" + condition + "'") +
                                   ")");
            }
        }
    }
}

// ---- typed reads: the value given, or the schema's default; checked against the schema ----------------

YAML::Node CaseReader::node(std::string_view path, const CaseKey& k) const {
    if (const auto it = entries_.find(path); it != entries_.end()) return it->second.node;
    if (k.default_value.empty())
        throw std::logic_error("case_reader: '" + std::string(path) + "' read with no value and no default");
    return YAML::Load(std::string(k.default_value));
}

void CaseReader::check_range(std::string_view path, const YAML::Node& n, double v, const CaseKey& k) const {
    const bool above_min = !k.min || (k.min->inclusive ? v >= k.min->value : v > k.min->value);
    const bool below_max = !k.max || (k.max->inclusive ? v <= k.max->value : v < k.max->value);
    if (!(above_min && below_max) && !(k.also && v == *k.also))
        fail(path, "must be " + range_text(k, true) + ", got " + n.Scalar(), &n);
}

double CaseReader::to_number(std::string_view path, const YAML::Node& n, const CaseKey& k) const {
    double v = 0.0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v)) fail(path, "expected a number, got " + describe(n), &n);
    if (!std::isfinite(v)) fail(path, "expected a finite number, got " + describe(n), &n);
    check_range(path, n, v, k);
    return v;
}

long CaseReader::to_integer(std::string_view path, const YAML::Node& n, const CaseKey& k) const {
    double v = 0.0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v) || std::floor(v) != v)
        fail(path, "expected an integer, got " + describe(n), &n);
    check_range(path, n, v, k);
    if (std::abs(v) > INT_MAX)
        fail(path, "is too large (at most " + std::to_string(INT_MAX) + "), got " + n.Scalar(), &n);
    return static_cast<long>(v);
}

// A list of exactly 2 items (`what`, e.g. "2 numbers like [1, 0]"), each read by `item`.
template <class T, class Item>
std::array<T, 2> CaseReader::read_pair(std::string_view path, const YAML::Node& n, const std::string& what,
                                       Item item) const {
    if (!n.IsSequence()) fail(path, "expected " + what + ", got " + describe(n), &n);
    if (n.size() != 2)
        fail(path,
             "expected " + what.substr(0, what.find(" like")) + ", got " + std::to_string(n.size()) +
                 (n.size() == 1 ? " item" : " items"),
             &n);
    std::array<T, 2> v{};
    std::size_t i = 0;
    for (const auto& element : n) v[i] = item(indexed(path, i), element), ++i;
    return v;
}

double CaseReader::number(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::number);
    return to_number(path, node(path, k), k);
}

long CaseReader::integer(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::integer);
    return to_integer(path, node(path, k), k);
}

bool CaseReader::boolean(std::string_view path) const {
    const YAML::Node n = node(path, key(path, KeyType::boolean));
    bool v = false;
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v))
        fail(path, "expected true or false, got " + describe(n), &n);
    return v;
}

std::string CaseReader::string(std::string_view path) const {
    const YAML::Node n = node(path, key(path, KeyType::string));
    if (!n.IsScalar()) fail(path, "expected a text, got " + describe(n), &n);
    return n.Scalar();
}

std::string CaseReader::choice(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::choice);
    const YAML::Node n = node(path, k);
    if (!n.IsScalar()) fail(path, "expected one of " + list(k.choices) + ", got " + describe(n), &n);
    const std::string& v = n.Scalar();
    if (std::find(k.choices.begin(), k.choices.end(), v) != k.choices.end()) return v;
    std::string reason = "invalid choice '" + v + "'; choices: " + list(k.choices);
    if (auto best = nearest(v, std::vector<std::string>(k.choices.begin(), k.choices.end())))
        reason += " (did you mean '" + *best + "'?)";
    fail(path, reason, &n);
}

std::array<double, 2> CaseReader::vector2(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::vector2);
    return read_pair<double>(path, node(path, k), "a list of 2 numbers like [1, 0]",
                             [&](const std::string& p, const YAML::Node& e) { return to_number(p, e, k); });
}

std::array<int, 2> CaseReader::integer_vector2(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::integer_vector2);
    return read_pair<int>(
        path, node(path, k), "a list of 2 integers like [2, 1]",
        [&](const std::string& p, const YAML::Node& e) { return static_cast<int>(to_integer(p, e, k)); });
}

std::vector<double> CaseReader::number_list(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::number_list);
    const YAML::Node n = node(path, k);
    if (!n.IsSequence()) fail(path, "expected a list of numbers like [0, 0.5, 1], got " + describe(n), &n);
    std::vector<double> v;
    for (const auto& element : n) v.push_back(to_number(indexed(path, v.size()), element, k));
    return v;
}

std::vector<std::string> CaseReader::string_list(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::string_list);
    const YAML::Node n = node(path, k);
    if (!n.IsSequence()) fail(path, "expected a list of texts like [a, b], got " + describe(n), &n);
    std::vector<std::string> v;
    for (const auto& element : n) {
        if (!element.IsScalar()) fail(indexed(path, v.size()), "expected a text, got " + describe(element), &element);
        v.push_back(element.Scalar());
    }
    return v;
}

std::vector<std::array<double, 2>> CaseReader::point_list(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::point_list);
    const YAML::Node n = node(path, k);
    if (!n.IsSequence()) fail(path, "expected a list of points like [[0.5, 0.5]], got " + describe(n), &n);
    std::vector<std::array<double, 2>> v;
    for (const auto& element : n)
        v.push_back(read_pair<double>(indexed(path, v.size()), element, "a point [x, y] like [0.5, 0.5]",
                                      [&](const std::string& p, const YAML::Node& e) { return to_number(p, e, k); }));
    return v;
}

std::optional<double> CaseReader::number_or_auto(std::string_view path) const {
    const CaseKey& k = key(path, KeyType::number_or_auto);
    const YAML::Node n = node(path, k);
    double v = 0.0;
    if (n.IsScalar() && n.Scalar() == "auto") return std::nullopt;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v) || !std::isfinite(v))
        fail(path, "expected auto or a number, got " + describe(n), &n);
    check_range(path, n, v, k);
    return v;
}

// ---- the documentation's key table --------------------------------------------------------------------

std::string markdown_table(const std::vector<CaseKey>& keys) {
    const auto cell = [](std::string_view text) {
        std::string s;
        for (char ch : text) s += ch == '|' ? std::string("\\|") : std::string(1, ch);
        return s;
    };
    const auto code = [](std::string_view text) { return "`" + std::string(text) + "`"; };
    std::string md =
        "| Key | Type | Default | Allowed | Units | Meaning |\n"
        "|-----|------|---------|---------|-------|---------|\n";
    for (const CaseKey& k : keys) {
        std::string type, allowed = range_text(k, false);
        switch (k.type) {
            case KeyType::section:
                type = "section";
                break;
            case KeyType::string:
                type = "text";
                break;
            case KeyType::number:
                type = "number";
                break;
            case KeyType::integer:
                type = "integer";
                break;
            case KeyType::boolean:
                type = "true/false";
                break;
            case KeyType::choice:
                type = "choice";
                break;
            case KeyType::vector2:
                type = "[number, number]";
                break;
            case KeyType::integer_vector2:
                type = "[integer, integer]";
                break;
            case KeyType::number_list:
                type = "list of numbers";
                break;
            case KeyType::string_list:
                type = "list of texts";
                break;
            case KeyType::point_list:
                type = "list of [x, y]";
                break;
            case KeyType::number_or_auto:
                type = "`auto` or number";
                break;
        }
        if (k.type == KeyType::choice) {
            for (std::string_view c : k.choices) allowed += (allowed.empty() ? "" : ", ") + code(c);
        }
        if ((k.type == KeyType::vector2 || k.type == KeyType::integer_vector2) && !allowed.empty())
            allowed = "each " + allowed;
        if (k.type == KeyType::number_or_auto) allowed = code("auto") + " or " + allowed;

        std::string dflt;
        if (k.required)
            dflt = "**required**";
        else if (!k.default_doc.empty())
            dflt = std::string(k.default_doc);
        else if (!k.default_value.empty())
            dflt = code(k.default_value);

        std::string meaning(k.meaning);
        if (!k.when_key.empty()) {
            // "Only with `spacing: tanh`." or "Only with `spacing: uniform`, `tanh` or `geometric`."
            const auto& values = k.when_values;
            std::string options = code(std::string(k.when_key) + ": " + std::string(values.front()));
            for (std::size_t i = 1; i < values.size(); ++i)
                options += (i + 1 == values.size() ? " or " : ", ") + code(values[i]);
            meaning += " Only with " + options + ".";
        }
        md += "| " + code(k.path) + " | " + cell(type) + " | " + cell(dflt) + " | " + cell(allowed) + " | " +
              cell(k.units) + " | " + cell(meaning) + " |\n";
    }
    return md;
}

}  // namespace chute
