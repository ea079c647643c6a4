// froth_fuzz: a deterministic mutation fuzzer for froth's file readers (issue 17).
//
//   froth_fuzz <reader> <seed files...> [--iterations N] [--seconds T] [--seed S] [--only K]
//              [--max-ms M] [--crashes DIR]
//
// Input k is seed file k mod #seeds with 1-4 mutations drawn from splitmix64(S, k): a token
// replaced by a hostile value (huge counts, negative tags, nan, inf, section names), a line
// deleted, duplicated or swapped, bytes flipped or inserted, the file cut short. Each input goes
// through the reader and, when that accepts it, the Cluster validation a read goes through in
// froth.read. A froth::Error is the expected outcome of bad input; anything else (another
// exception, a crash caught by the sanitizers, an input slower than --max-ms) fails the run.
// The failing input is written to DIR (default: the working directory) and `--only K` replays
// it. --seconds is the time budget: the run stops early (and says so) rather than overrun CI.
// Run under ASan/UBSan in CI (.ci/run) so memory errors abort at the first bad access.
#include "core/errors.h"
#include "io/msh_reader.h"
#include "io/state_file.h"
#include "mesh/cluster.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct Reader {
    const char* name;
    std::function<froth::Cluster(std::string_view)> read; ///< reads and builds the cluster
};

/// A mutated state file sealed again with a correct checksum, so that the mutations reach the
/// parser and the cluster's checks instead of stopping at the checksum.
froth::Cluster read_resealed_state(std::string_view text) {
    std::string sealed(text);
    const std::size_t mark = sealed.rfind("\nchecksum ");
    if (mark != std::string::npos)
        sealed = sealed.substr(0, mark + 1) + "checksum " +
                 froth::state_checksum(std::string_view(sealed).substr(0, mark + 1)) + "\n";
    const froth::StateResolvers given{
        [](int, const std::string&) {
            return froth::make_function_wall([](const froth::Vec3& x) { return x[2]; }, {}, "z");
        },
        [](int) { return froth::Mobility::constant(2); },
        [](int, const std::string& name) {
            return std::make_shared<const froth::Curve>(
                [](double p) { return froth::Vec3(std::cos(p), std::sin(p), 0); }, name);
        }};
    return froth::restore_cluster(froth::parse_state_file(sealed, "fuzz.froth"), given);
}

const Reader kReaders[] = {
    {"msh", [](std::string_view text) { return froth::Cluster(froth::parse_msh(text, "fuzz.msh")); }},
    {"state", read_resealed_state},
};

/// splitmix64: the same stream on every platform (std:: distributions are not portable).
struct Random {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
};

const char* const kHostile[] = {
    "-1",
    "0",
    "1",
    "2",
    "3",
    "4",
    "-2147483648",
    "2147483647",
    "2147483648",
    "2000000000",
    "1000000000000",
    "9223372036854775807",
    "18446744073709551616",
    "nan",
    "inf",
    "-inf",
    "1e308",
    "1e300",
    "-1e300",
    "1e-300",
    "0x10",
    "+5",
    "4.1",
    "2.2",
    "1.0",
    "$Nodes",
    "$EndNodes",
    "$Elements",
    "$EndElements",
    "$Entities",
    "$EndEntities",
    "$PhysicalNames",
    "$MeshFormat",
    "\"",
    "\"name with space",
    "",
    "99",
    "15",
    "31",
};

std::vector<std::size_t> line_starts(const std::string& s) {
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i] == '\n' && i + 1 < s.size()) starts.push_back(i + 1);
    return starts;
}

std::pair<std::size_t, std::size_t> line_at(const std::string& s, std::size_t start) {
    const std::size_t end = s.find('\n', start);
    return {start, end == std::string::npos ? s.size() : end + 1};
}

void replace_token(std::string& s, Random& r) {
    if (s.empty()) return;
    std::size_t i = r.below(s.size());
    while (i > 0 && !std::isspace(static_cast<unsigned char>(s[i - 1])))
        --i;
    std::size_t j = i;
    while (j < s.size() && !std::isspace(static_cast<unsigned char>(s[j])))
        ++j;
    s.replace(i, j - i, kHostile[r.below(std::size(kHostile))]);
}

void mutate_lines(std::string& s, Random& r) {
    const std::vector<std::size_t> starts = line_starts(s);
    auto [a, b] = line_at(s, starts[r.below(starts.size())]);
    const std::string line = s.substr(a, b - a);
    switch (r.below(3)) {
    case 0:
        s.erase(a, b - a);
        break;
    case 1:
        s.insert(a, line);
        break;
    default: {
        auto [c, d] = line_at(s, starts[r.below(starts.size())]);
        if (c > a) {
            const std::string other = s.substr(c, d - c);
            s.replace(c, d - c, line);
            s.replace(a, b - a, other);
        }
    }
    }
}

void mutate_bytes(std::string& s, Random& r) {
    switch (r.below(3)) {
    case 0:
        if (!s.empty()) s[r.below(s.size())] ^= static_cast<char>(1u << r.below(8));
        break;
    case 1:
        s.insert(r.below(s.size() + 1), 1, static_cast<char>(r.below(256)));
        break;
    default:
        s.resize(r.below(s.size() + 1));
        break; // cut short
    }
}

std::string mutated(const std::string& seed, std::uint64_t base, std::uint64_t k) {
    Random r{base * 0x100000001b3ULL + k};
    std::string s = seed;
    const std::size_t n = 1 + r.below(4);
    for (std::size_t m = 0; m < n; ++m) {
        const std::size_t kind = r.below(10);
        if (kind < 6)
            replace_token(s, r);
        else if (kind < 8)
            mutate_lines(s, r);
        else
            mutate_bytes(s, r);
    }
    return s;
}

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read seed '" + path + "'");
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

/// "ok" / "error" for the expected outcomes; throws anything unexpected through.
const char* run_one(const Reader& reader, const std::string& input) {
    try {
        const froth::Cluster c = reader.read(input);
        return "ok";
    } catch (const froth::Error&) {
        return "error";
    }
}

[[noreturn]] void usage() {
    std::cerr << "usage: froth_fuzz <reader: msh | state> <seed files...> [--iterations N] [--seconds T] "
                 "[--seed S] [--only K] [--max-ms M] [--crashes DIR]\n";
    std::exit(2);
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) usage();
    const Reader* reader = nullptr;
    for (const Reader& r : kReaders)
        if (std::string_view(argv[1]) == r.name) reader = &r;
    if (!reader) usage();
    std::vector<std::string> seeds;
    long long iterations = 10000, only = -1;
    std::uint64_t base = 1;
    double max_ms = 2000, budget_s = 600;
    std::string crashes = ".";
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] {
            if (i + 1 >= argc) usage();
            return std::string(argv[++i]);
        };
        if (a == "--iterations")
            iterations = std::stoll(value());
        else if (a == "--seed")
            base = std::stoull(value());
        else if (a == "--only")
            only = std::stoll(value());
        else if (a == "--max-ms")
            max_ms = std::stod(value());
        else if (a == "--seconds")
            budget_s = std::stod(value());
        else if (a == "--crashes")
            crashes = value();
        else
            seeds.push_back(slurp(a));
    }
    if (seeds.empty()) usage();

    long long accepted = 0, rejected = 0, slowest_k = -1;
    double slowest = 0;
    const auto start = std::chrono::steady_clock::now();
    bool out_of_time = false;
    for (long long k = only >= 0 ? only : 0; k < (only >= 0 ? only + 1 : iterations); ++k) {
        if (k % 256 == 0 &&
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
                budget_s) {
            out_of_time = true;
            break;
        }
        const std::string input = mutated(seeds[k % seeds.size()], base, k);
        const auto t0 = std::chrono::steady_clock::now();
        std::string outcome;
        try {
            outcome = run_one(*reader, input);
        } catch (const std::exception& e) {
            outcome = std::string("unexpected exception: ") + e.what();
        } catch (...) {
            outcome = "unexpected non-standard exception";
        }
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        if (ms > slowest) slowest = ms, slowest_k = k;
        if (outcome != "ok" && outcome != "error") {
            const std::string path =
                crashes + "/fuzz_" + reader->name + "_" + std::to_string(k) + ".in";
            std::ofstream(path, std::ios::binary) << input;
            std::cerr << "input " << k << ": " << outcome << " (saved as " << path << ")\n";
            return 1;
        }
        (outcome == "ok" ? accepted : rejected) += 1;
    }
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("froth_fuzz %s: %lld inputs from %zu seeds (seed %llu): %lld read, %lld refused "
                "with a froth error, 0 failures; slowest input %lld: %.1f ms; %.1f s%s\n",
                reader->name, accepted + rejected, seeds.size(),
                static_cast<unsigned long long>(base), accepted, rejected, slowest_k, slowest, s,
                out_of_time ? " (stopped by the time budget)" : "");
    if (slowest > max_ms) {
        std::cerr << "input " << slowest_k << " took " << slowest << " ms (limit " << max_ms
                  << " ms): a hang in the making\n";
        return 1;
    }
    return 0;
}
