// Fuzzing the case-file reader (run/case_file.cpp over io/case_reader.cpp and the modules' *_keys.cpp).
//
// Checks: 12,000 deterministic mutations of the example cases (every examples/*/*.yaml; tests/fuzz/
// case_mutator.hpp: bytes, lines, indentation, tabs, extreme values, nesting past yaml-cpp's depth guard,
// keys, broken YAML, --set overrides) are each either read or rejected with a chute::CaseError; no other
// exception, no crash (a crash ends the test binary: ctest reports it). Every rejection names where: a key
// path of the schema (the "path: reason" of every message), the --set that caused it, or a line of the
// text. A case read is one the solver can make its grid from. No input takes longer than 1 s (a hang; 5 s
// in Debug and sanitizer builds, which run the first 4000 inputs only, several times slower). The inputs
// are shared out between the ranks (unit_np2) and the counts summed. A failure is reported with its input
// number, base file, seed and mutations, and the text.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../fuzz/case_mutator.hpp"
#include "axis.hpp"
#include "case_file.hpp"
#include "example_cases.hpp"
#include "print_on_rank0.hpp"

namespace chute {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kSeed = 20240614;
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
constexpr int kInputs = 12000;
constexpr double kHangSeconds = 1.0;
#else
// Debug and sanitizer builds (scripts/test-sanitizers.sh): the first 4000 of the same inputs, as ASan's
// allocator bookkeeping makes the reader's many small allocations ten times slower (12,000 took 135 s).
constexpr int kInputs = 4000;
constexpr double kHangSeconds = 5.0;
#endif

struct BaseCase {
    std::string file, text;
};

std::vector<BaseCase> example_cases() {
    std::vector<BaseCase> cases;
    for (const fs::path& file : flow_example_cases()) {
        std::ifstream in(file);
        std::stringstream s;
        s << in.rdbuf();
        cases.push_back({fs::relative(file, CHUTE_SOURCE_DIR).string(), s.str()});
    }
    std::sort(cases.begin(), cases.end(), [](const BaseCase& a, const BaseCase& b) { return a.file < b.file; });
    return cases;
}

// Every key path of the schema with its placeholders filled in (twice, with different names), for overrides.
std::vector<std::string> concrete_paths() {
    std::vector<std::string> paths;
    for (const CaseKey& k : case_schema())
        for (const auto& [axis, side, body] :
             {std::array<std::string, 3>{"x", "left", "block"}, std::array<std::string, 3>{"y", "top", "cylinder"}}) {
            std::string p(k.path);
            for (const auto& [from, to] :
                 {std::pair<std::string, std::string>{"<axis>", axis}, {"<side>", side}, {"<body>", body}})
                if (const auto at = p.find(from); at != std::string::npos) p.replace(at, from.size(), to);
            if (paths.empty() || paths.back() != p) paths.push_back(p);
        }
    return paths;
}

// Does the concrete path ("bodies.block.motion.type", "output.probes[2]") match a key of the schema?
bool is_schema_key(std::string path) {
    path = std::regex_replace(path, std::regex(R"(\[\d+\])"), "");
    std::vector<Placeholder> placeholders = flow_placeholders();
    for (Placeholder& p : body_placeholders()) placeholders.push_back(std::move(p));
    const auto split = [](const std::string& s) {
        std::vector<std::string> parts;
        std::stringstream in(s);
        for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
        return parts;
    };
    const auto concrete = split(path);
    for (const CaseKey& k : case_schema()) {
        const auto pattern = split(std::string(k.path));
        if (pattern.size() != concrete.size()) continue;
        bool same = true;
        for (std::size_t i = 0; i < pattern.size() && same; ++i) {
            if (pattern[i] == concrete[i]) continue;
            same = false;
            for (const Placeholder& p : placeholders)
                if (p.segment == pattern[i])
                    same = p.names.empty() ? !concrete[i].empty()
                                           : std::find(p.names.begin(), p.names.end(), concrete[i]) != p.names.end();
        }
        if (same) return true;
    }
    return false;
}

// Does the rejection say where: a line of the text, the --set that caused it, or a key path of the schema
// before its reason ("domain.x.cells: expected an integer")?
bool names_where(const std::string& message, const std::string& text) {
    if (message.starts_with("--set ")) return true;
    const long lines = std::count(text.begin(), text.end(), '\n') + 1;
    std::smatch m;
    if (std::regex_search(message, m, std::regex(R"(line (\d+))")) && std::stol(m[1]) >= 1 &&
        std::stol(m[1]) <= lines + 1)
        return true;
    static const std::regex key_before_reason(R"(([A-Za-z0-9_.\[\]-]+): )");
    for (auto it = std::sregex_iterator(message.begin(), message.end(), key_before_reason);
         it != std::sregex_iterator(); ++it)
        if (is_schema_key((*it)[1])) return true;
    return false;
}

std::string shortened(const std::string& s) { return s.size() <= 2000 ? s : s.substr(0, 2000) + "\n[...]"; }

TEST(CaseFuzz, MutatedCasesAreReadOrRejectedNamingWhere) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const std::vector<BaseCase> bases = example_cases();
    ASSERT_GE(bases.size(), 10u) << "the examples are the fuzzer's seeds";
    const std::vector<std::string> paths = concrete_paths();

    long counts[4] = {0, 0, 0, 0};  // inputs, accepted, rejected, failures
    double slowest = 0.0, total_seconds = 0.0;
    for (int i = rank; i < kInputs; i += size) {
        const BaseCase& base = bases[static_cast<std::size_t>(i) % bases.size()];
        fuzz::CaseMutator mutator(kSeed + static_cast<std::uint64_t>(i));
        // Mostly the text mutated; one input in 8 only its overrides, so the overrides reach the deep checks.
        const bool overrides_only = mutator.coin(8);
        const std::string text =
            overrides_only ? base.text : mutator.any(base.text, 1 + static_cast<int>(mutator.pick(3)));
        std::vector<std::string> overrides;
        if (overrides_only || mutator.coin(4))
            for (std::size_t n = 1 + mutator.pick(3); n > 0; --n) overrides.push_back(mutator.override_text(paths));

        std::string failure;
        const auto start = std::chrono::steady_clock::now();
        try {
            const CaseConfig c = parse_case_text(text, overrides);
            ++counts[1];
            // What the reader accepts, the solver must take: its grid is made from these lines.
            try {
                for (const AxisConfig* a : {&c.x, &c.y}) Axis(axis_lines(*a), false);
            } catch (const std::exception& e) {
                failure = "accepted, but its grid cannot be made: " + std::string(e.what());
            }
        } catch (const CaseError& e) {
            ++counts[2];
            if (!names_where(e.what(), text))
                failure = "the rejection names no key, --set or line: " + std::string(e.what());
        } catch (const std::exception& e) {
            failure = "an exception other than CaseError: " + std::string(e.what());
        } catch (...) {
            failure = "an exception that is not a std::exception";
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++counts[0];
        slowest = std::max(slowest, seconds);
        total_seconds += seconds;
        if (seconds > kHangSeconds)
            failure += (failure.empty() ? "" : "; ") + std::string("took ") + std::to_string(seconds) + " s";
        if (!failure.empty()) {
            ++counts[3];
            std::ostringstream report;
            report << "input " << i << " (" << base.file << ", seed " << kSeed + i << "): " << failure
                   << "\nmutations: " << mutator.log() << "\ntext:\n"
                   << shortened(text);
            ADD_FAILURE() << report.str();
            if (rank != 0) std::fprintf(stderr, "rank %d: %s\n", rank, report.str().c_str());
        }
    }
    MPI_Allreduce(MPI_IN_PLACE, counts, 4, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &slowest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &total_seconds, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    print_on_rank0(
        "case fuzz: %ld inputs from %zu example cases (seed %llu): %ld read, %ld rejected with a CaseError, %ld "
        "failures; reading took %.2f s in all, at most %.3f s for one input\n",
        counts[0], bases.size(), static_cast<unsigned long long>(kSeed), counts[1], counts[2], counts[3], total_seconds,
        slowest);
    EXPECT_EQ(counts[0], kInputs);
    EXPECT_EQ(counts[1] + counts[2], kInputs);
    // Not a fuzz that only ever breaks the YAML: a share of the mutated cases must still be read.
    EXPECT_GT(counts[1], kInputs / 20);
}

}  // namespace
}  // namespace chute
