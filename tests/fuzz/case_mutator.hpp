#pragma once
// Mutated case files for fuzzing the case-file reader (tests/unit/test_case_fuzz.cpp) and the whole run
// (tests/validation/test_case_fuzz_runs.cpp). Deterministic: a mutator seeded with the same number makes
// the same case, so a failing input is reproduced from its seed alone.
//
// Two kinds of mutation:
//   - any(): everything a hand, an editor or a broken file can do to a case: byte flips, inserts and
//     deletes (binary bytes too), lines deleted, duplicated, swapped or re-indented, tabs, values swapped for
//     extremes (0, -1, +-1e300, nan, .inf, "", [], {}, long texts and lists, [[[[...]]]] nested thousands
//     deep), keys misspelt, removed or duplicated, YAML broken (unbalanced brackets, stray colons, anchors
//     and aliases, several documents, directives, tags).
//   - value(): one value swapped for an extreme or rescaled, the YAML kept valid, so that a good share of
//     the mutated cases pass the reader and actually run.
// Overrides (--set key=value) are mutated the same way: made from the schema's own paths and then mangled.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace chute::fuzz {

// A scalar of the text: where it starts and how long it is.
struct Span {
    std::size_t at, size;
};

class CaseMutator {
public:
    explicit CaseMutator(std::uint64_t seed) {
        std::seed_seq s{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)};
        rng_.seed(s);
    }

    // What was done, for the report of a failing input.
    const std::string& log() const { return log_; }

    // `count` mutations of any kind.
    std::string any(std::string text, int count) {
        for (int i = 0; i < count; ++i) text = any_once(text);
        return text;
    }

    // One value replaced by an extreme or a rescaled copy; the YAML stays valid.
    std::string value(const std::string& text) {
        const std::vector<Span> values = scalars(text, false);
        if (values.empty()) return text;
        const Span s = values[pick(values.size())];
        const std::string old = text.substr(s.at, s.size);
        const std::string now = replacement(old);
        note("value '" + old + "' -> '" + now + "'");
        return text.substr(0, s.at) + now + text.substr(s.at + s.size);
    }

    // What a scalar value `old` is swapped for when the YAML must stay valid: a rescaled copy of a number
    // (x10, x0.1, x2, x0.5, negated, +1) or an extreme.
    std::string replacement(const std::string& old) {
        const std::string r = coin(2) ? rescaled(old) : old;
        return r != old ? r : pick_of(kValidExtremes);  // a word is not rescaled: always an extreme
    }

    // A --set override: a key path of the schema (placeholders filled in) with a value, then perhaps mangled.
    std::string override_text(const std::vector<std::string>& paths) {
        std::string path = paths[pick(paths.size())];
        std::string value = coin(2) ? pick_of(kValidExtremes) : extreme();
        std::string o = path + "=" + value;
        switch (pick(6)) {
            case 0:
                o = bytes(o);
                break;
            case 1:
                o = path;  // no '='
                break;
            case 2:
                o = path + "." + path + "=" + value;  // a sub-key of a value
                break;
            case 3:
                o = misspelt(path) + "=" + value;
                break;
            default:
                break;
        }
        note("--set " + shortened(o));
        return o;
    }

    // Deeply nested flow sequence or mapping: [[[...]]] or {a: {a: ...}}.
    static std::string nested(std::size_t depth, bool mapping) {
        std::string s;
        for (std::size_t i = 0; i < depth; ++i) s += mapping ? "{a: " : "[";
        s += "1";
        for (std::size_t i = 0; i < depth; ++i) s += mapping ? "}" : "]";
        return s;
    }

    std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
    bool coin(std::size_t one_in) { return pick(one_in) == 0; }

private:
    // Values that keep YAML valid: the reader's range checks see them.
    // clang-format off
    inline static const std::vector<std::string> kValidExtremes = {
        "0", "-1", "1", "2", "0.5", "-0.5", "100", "1e6", "1e7", "-1e6", "1e-9", "1e300", "-1e300", "1e-300",
        "4.9e-324", "1.7976931348623157e308", ".nan", "nan", ".inf", "-.inf", "2147483647", "2147483648",
        "-2147483649", "true", "false", "auto", "abc", "''", "~", "[]", "{}", "[0, 0]", "[1e300, 0]", "[0, 1e6]",
        "[[0, 0]]", "[0, 0, 0]"};
    // clang-format on

    std::string extreme() {
        switch (pick(10)) {
            case 0:
                return std::string(pick(2) ? 100000 : 1000, 'a');  // long text
            case 1: {                                              // long list
                std::string s = "[";
                const std::size_t n = coin(2) ? 10000 : 100;
                for (std::size_t i = 0; i < n; ++i) s += (i ? ", " : "") + std::to_string(i);
                return s + "]";
            }
            case 2:  // nested below, at and above yaml-cpp's depth guard (2000)
                return nested(pick_of(std::vector<std::size_t>{10, 500, 1999, 2000, 2001, 5000, 100000}), coin(2));
            case 3:
                return "\"" + std::string(1, static_cast<char>(pick(256))) + "\"";
            case 4:
                return "1" + std::string(400, '0');  // beyond double
            case 5:
                return pick_of(std::vector<std::string>{"*a", "&a 1", "!!binary AAAA", "!!str 3", "|\n  text", "0x1F",
                                                        "1_000", ".5", "+1", "0o17", "yes", "no", "'1'", "\"\\0\""});
            case 6:  // the integers and magnitudes at the edges of what a grid or a count can be
                return pick_of(std::vector<std::string>{"2147483647", "1e6", "1e7", "1e8", "1e300", "1", "0", "-1"});
            default:
                return pick_of(kValidExtremes);
        }
    }

    std::string any_once(const std::string& text) {
        if (text.empty()) return std::string(1, static_cast<char>(pick(256)));
        switch (pick(17)) {
            case 0:
                return bytes(text);
            case 1: {  // delete a line
                auto lines = split_lines(text);
                const std::size_t k = pick(lines.size());
                note("delete line " + std::to_string(k + 1));
                lines.erase(lines.begin() + static_cast<long>(k));
                return join_lines(lines);
            }
            case 2: {  // duplicate a line (keys given twice)
                auto lines = split_lines(text);
                const std::size_t k = pick(lines.size());
                note("duplicate line " + std::to_string(k + 1));
                lines.insert(lines.begin() + static_cast<long>(k), lines[k]);
                return join_lines(lines);
            }
            case 3: {  // swap two lines
                auto lines = split_lines(text);
                const std::size_t a = pick(lines.size()), b = pick(lines.size());
                note("swap lines " + std::to_string(a + 1) + " and " + std::to_string(b + 1));
                std::swap(lines[a], lines[b]);
                return join_lines(lines);
            }
            case 4: {  // indentation changed, or a tab
                auto lines = split_lines(text);
                const std::size_t k = pick(lines.size());
                switch (pick(4)) {
                    case 0:
                        lines[k] = std::string(1 + pick(4), ' ') + lines[k];
                        break;
                    case 1:
                        lines[k].erase(0, std::min(lines[k].find_first_not_of(' '), 1 + pick(4)));
                        break;
                    case 2:
                        lines[k] = "\t" + lines[k];
                        break;
                    default:
                        lines[k].insert(pick(lines[k].size() + 1), "\t");
                }
                note("indentation of line " + std::to_string(k + 1));
                return join_lines(lines);
            }
            case 5:
            case 6:
            case 7: {  // a value swapped for an extreme, valid or not
                const std::vector<Span> values = scalars(text, false);
                if (values.empty()) return bytes(text);
                const Span s = values[pick(values.size())];
                const std::string now = extreme();
                note("value '" + text.substr(s.at, s.size) + "' -> '" + shortened(now) + "'");
                return text.substr(0, s.at) + now + text.substr(s.at + s.size);
            }
            case 8:
                return value(text);
            case 9: {  // a key misspelt
                const std::vector<Span> keys = scalars(text, true);
                if (keys.empty()) return bytes(text);
                const Span s = keys[pick(keys.size())];
                const std::string now = misspelt(text.substr(s.at, s.size));
                note("key '" + text.substr(s.at, s.size) + "' -> '" + now + "'");
                return text.substr(0, s.at) + now + text.substr(s.at + s.size);
            }
            case 10: {  // a key replaced by another key of the text (a known key in the wrong place, or twice)
                const std::vector<Span> keys = scalars(text, true);
                if (keys.size() < 2) return bytes(text);
                const Span s = keys[pick(keys.size())], t = keys[pick(keys.size())];
                note("key '" + text.substr(s.at, s.size) + "' -> '" + text.substr(t.at, t.size) + "'");
                return text.substr(0, s.at) + text.substr(t.at, t.size) + text.substr(s.at + s.size);
            }
            case 11: {  // a key with its whole line removed, value and all
                const std::vector<Span> keys = scalars(text, true);
                if (keys.empty()) return bytes(text);
                const Span s = keys[pick(keys.size())];
                const std::size_t b = text.rfind('\n', s.at), e = text.find('\n', s.at);
                const std::size_t from = b == std::string::npos ? 0 : b, to = e == std::string::npos ? text.size() : e;
                note("remove the line of key '" + text.substr(s.at, s.size) + "'");
                return text.substr(0, from) + text.substr(to);
            }
            case 12:
            case 13: {  // YAML broken
                static const std::vector<std::string> breakers = {"[",
                                                                  "]",
                                                                  "{",
                                                                  "}",
                                                                  ":",
                                                                  ": :",
                                                                  "&a ",
                                                                  "*a",
                                                                  "*undefined",
                                                                  "\n---\n",
                                                                  "\n...\n",
                                                                  "%YAML 1.2\n",
                                                                  "? ",
                                                                  "!!int ",
                                                                  "!<tag> ",
                                                                  "|",
                                                                  ">",
                                                                  "- ",
                                                                  ",",
                                                                  "'",
                                                                  "\"",
                                                                  "<<: *a\n",
                                                                  "&a [*a]",
                                                                  "\n- item\n",
                                                                  "#",
                                                                  "@",
                                                                  "`",
                                                                  "%",
                                                                  "\xef\xbb\xbf",
                                                                  "\xff\xfe",
                                                                  "\r"};
                const std::string b = pick_of(breakers);
                const std::size_t at = pick(text.size() + 1);
                note("insert '" + b + "' at byte " + std::to_string(at));
                return text.substr(0, at) + b + text.substr(at);
            }
            case 14: {  // a whole document of something else
                static const std::vector<std::string> documents = {"",
                                                                   "~",
                                                                   "[]",
                                                                   "{}",
                                                                   "- a\n- b\n",
                                                                   "just text",
                                                                   std::string("\x00\x01\x02", 3),
                                                                   "---\n---\n",
                                                                   "a: b\n---\nc: d\n"};
                note("whole document replaced");
                return pick_of(documents);
            }
            case 15: {  // the text cut short
                const std::size_t at = pick(text.size());
                note("cut at byte " + std::to_string(at));
                return text.substr(0, at);
            }
            default: {  // an anchor on one value and an alias in place of another
                const std::vector<Span> values = scalars(text, false);
                if (values.size() < 2) return bytes(text);
                Span a = values[pick(values.size())], b = values[pick(values.size())];
                if (a.at > b.at) std::swap(a, b);
                if (a.at == b.at) return text;
                note("anchor on '" + text.substr(a.at, a.size) + "', alias for '" + text.substr(b.at, b.size) + "'");
                return text.substr(0, a.at) + "&v " + text.substr(a.at, b.at - a.at) + "*v" +
                       text.substr(b.at + b.size);
            }
        }
    }

    // Byte-level damage: flips, inserts (any byte, binary too), deletes of a byte or a run.
    std::string bytes(std::string s) {
        if (s.empty()) return std::string(1, static_cast<char>(pick(256)));
        const std::size_t at = pick(s.size());
        switch (pick(4)) {
            case 0:
                s[at] = static_cast<char>(s[at] ^ (1 << pick(8)));
                note("flip a bit of byte " + std::to_string(at));
                break;
            case 1:
                s.insert(at, 1, static_cast<char>(pick(256)));
                note("insert a byte at " + std::to_string(at));
                break;
            case 2:
                s.erase(at, 1);
                note("delete byte " + std::to_string(at));
                break;
            default: {
                const std::size_t n = 1 + pick(std::min<std::size_t>(s.size() - at, 40));
                s.erase(at, n);
                note("delete " + std::to_string(n) + " bytes at " + std::to_string(at));
            }
        }
        return s;
    }

    std::string misspelt(std::string key) {
        if (key.empty()) return "x";
        const std::size_t at = pick(key.size());
        switch (pick(4)) {
            case 0:
                key.erase(at, 1);
                break;
            case 1:
                key.insert(at, 1, static_cast<char>('a' + pick(26)));
                break;
            case 2:
                key[at] = static_cast<char>('a' + pick(26));
                break;
            default:
                if (at + 1 < key.size()) std::swap(key[at], key[at + 1]);
        }
        return key;
    }

    // A number rescaled (x10, x0.1, x2, x0.5, negated, +1), or a word left as it is.
    std::string rescaled(const std::string& old) {
        double v = 0.0;
        try {
            std::size_t used = 0;
            v = std::stod(old, &used);
            if (used != old.size()) return old;
        } catch (const std::exception&) {
            return old;
        }
        static const std::vector<double> factors = {10.0, 0.1, 2.0, 0.5, -1.0, 100.0, 0.01};
        const bool integer = old.find_first_of(".eE") == std::string::npos;
        if (coin(7)) return integer ? std::to_string(static_cast<long long>(v) + 1) : std::to_string(v + 1.0);
        const double w = v * pick_of(factors);
        if (integer) return std::to_string(static_cast<long long>(w));
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", w);
        return buf;
    }

    // The scalars of the text that are values (`keys` false) or keys (true): runs of plain characters after
    // ':', '[', ',' or '-' (values) or followed by ':' (keys), outside comments.
    static std::vector<Span> scalars(const std::string& text, bool keys) {
        std::vector<Span> found;
        const auto plain = [](char c) {
            return c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != ',' && c != ':' && c != '[' && c != ']' &&
                   c != '{' && c != '}' && c != '#';
        };
        std::size_t i = 0;
        while (i < text.size()) {
            if (text[i] == '#' && (i == 0 || text[i - 1] == ' ' || text[i - 1] == '\n')) {
                i = text.find('\n', i);
                if (i == std::string::npos) break;
                continue;
            }
            if (!plain(text[i])) {
                ++i;
                continue;
            }
            const std::size_t b = i;
            while (i < text.size() && plain(text[i])) ++i;
            std::size_t after = i;
            while (after < text.size() && text[after] == ' ') ++after;
            const bool is_key = after < text.size() && text[after] == ':';
            std::size_t before = b;
            while (before > 0 && text[before - 1] == ' ') --before;
            const char prev = before == 0 ? '\n' : text[before - 1];
            const bool after_value_mark = prev == ':' || prev == '[' || prev == ',' || prev == '-';
            if (keys ? is_key : (!is_key && after_value_mark)) found.push_back({b, i - b});
        }
        return found;
    }

    static std::vector<std::string> split_lines(const std::string& text) {
        std::vector<std::string> lines;
        std::size_t b = 0;
        for (std::size_t e = text.find('\n'); e != std::string::npos; b = e + 1, e = text.find('\n', b))
            lines.push_back(text.substr(b, e - b));
        lines.push_back(text.substr(b));
        return lines;
    }

    static std::string join_lines(const std::vector<std::string>& lines) {
        std::string s;
        for (std::size_t i = 0; i < lines.size(); ++i) s += (i ? "\n" : "") + lines[i];
        return s;
    }

    static std::string shortened(const std::string& s) { return s.size() <= 60 ? s : s.substr(0, 57) + "..."; }

    template <class T>
    T pick_of(const std::vector<T>& items) {
        return items[pick(items.size())];
    }

    void note(const std::string& what) { log_ += (log_.empty() ? "" : "; ") + what; }

    std::mt19937 rng_;
    std::string log_;
};

}  // namespace chute::fuzz
