// froth_bench_step: the cost of one time step of each flow (docs/benchmarks.md).
//
// For every target edge length h it times three cases:
//   mcf on the double bubble  (CHOLMOD SPD system)      check: max relative energy change of a step
//   mcf on the unit sphere    (the same solver)         check: |R(t)^2 - (1 - 4t)|, exact solution
//                                                       (R = mean vertex distance from the origin)
//   sd  on the double bubble  (UMFPACK saddle point)    check: max relative volume loss
// Each case: one "first step" (symbolic analysis, first numeric factorisation and, for sd, the
// kappa basis), a few warm-up steps, then `repeat` blocks of N timed steps ("steps" = repeat x
// N); s/step is the best block's mean and the shares are that block's solve/total and
// assemble/total (total = the wall time of TimeStepper::step, which also checks facets and
// computes the report). The solvers reuse a numeric factorisation as a GMRES preconditioner
// until it needs more than a few iterations (solvers/sparse_solvers.h), so the cost of a step
// depends on how old the factor is and a block without a refactorisation is cheap: "mean
// s/step", "refact" (refactorisations) and "GMRES it" (iterations per step) are therefore taken
// over all timed steps. N is chosen so a block takes about `--seconds`, and is at least
// `--min-steps` (30: of the order of the refactorisation interval; MCF blocks are capped so that
// t <= 0.125, before the sphere, which vanishes at t = 1/4, gets small).
//
// Output: markdown table rows on stdout (progress on stderr). Exit status 1 if a check fails.

#include "builders/gmsh_builder.h"
#include "core/errors.h"
#include "flows/stepper.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#ifndef FROTH_BUILD_TYPE
#define FROTH_BUILD_TYPE "unknown"
#endif

namespace {

using Clock = std::chrono::steady_clock;
using froth::Flow;

struct Options {
    std::vector<double> sizes{0.08, 0.04, 0.02};
    double tau = 1e-3;
    double seconds = 3.0; // target wall time of one timed block
    int warmup = 2;       // steps after the first step, before timing
    int repeat = 3;       // timed blocks; the best is reported
    int steps = 0;        // fixed N (0: choose from `seconds`)
    int min_steps = 30;   // smallest N chosen from `seconds`
    bool quick = false;
    std::vector<std::string> cases{"mcf", "sphere", "sd"};
};

enum class Scene { DoubleBubble, Sphere };

struct Case {
    Flow flow;
    Scene scene;
};

struct Row {
    std::string flow, scene;
    double h = 0;
    int vertices = 0, unknowns = 0, steps = 0, blocks = 0;
    double mean_per_step = 0;  // over all timed steps
    int refactorizations = 0;  // over all timed steps
    double iterations = 0;     // GMRES iterations per timed step
    double t = 0, build_s = 0, first_s = 0, per_step = 0, solve_share = 0, assemble_share = 0;
    std::string check;
    bool ok = true;
};

// Loose bounds: the checks must catch a broken scheme, not grade accuracy.
constexpr double kSphereTol = 1e-2;   // |R^2 - (1 - 4t)| after a few steps of tau = 1e-3
constexpr double kVolumeTol = 1e-2;   // relative volume loss (seed: 1.1e-3 at T = 1)
constexpr double kEnergyTol = 1e-10;  // relative energy increase of a step (stability)
constexpr double kMcfTime = 0.125;    // MCF rows stop by this time (sphere: R^2 = 1/2)

[[noreturn]] void usage(int status) {
    std::fprintf(status ? stderr : stdout,
                 "usage: froth_bench_step [--sizes h1,h2,...] [--quick] [--repeat R]\n"
                 "                        [--seconds S] [--steps N] [--warmup W] [--tau T]\n"
                 "  --sizes    target edge lengths (default 0.08,0.04,0.02: ~3k, 12k, 47k vertices)\n"
                 "  --quick    smoke run: h = 0.15, no warm-up, 1 block of 2 steps\n"
                 "  --repeat   timed blocks per case, best reported (default 3)\n"
                 "  --seconds  target wall time of one block (default 3)\n"
                 "  --steps    fixed steps per block instead of --seconds\n"
                 "  --min-steps  smallest steps per block chosen from --seconds (default 30)\n"
                 "  --warmup   steps between the first step and timing (default 2)\n"
                 "  --tau      time step (default 1e-3)\n"
                 "  --cases    any of mcf (double bubble), sphere (mcf), sd (double bubble);\n"
                 "             default mcf,sphere,sd\n");
    std::exit(status);
}

double to_double(const char* s, const char* what) {
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || *end != '\0' || !std::isfinite(v)) {
        std::fprintf(stderr, "froth_bench_step: bad %s '%s'\n", what, s);
        usage(2);
    }
    return v;
}

Options parse(int argc, char** argv) {
    Options o;
    bool sizes_given = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "froth_bench_step: %s needs a value\n", a.c_str());
                usage(2);
            }
            return argv[++i];
        };
        if (a == "-h" || a == "--help") usage(0);
        else if (a == "--quick") o.quick = true;
        else if (a == "--sizes") {
            o.sizes.clear();
            std::stringstream ss(value());
            for (std::string item; std::getline(ss, item, ',');)
                if (!item.empty()) o.sizes.push_back(to_double(item.c_str(), "size"));
            if (o.sizes.empty()) usage(2);
            sizes_given = true;
        } else if (a == "--repeat") o.repeat = std::max(1, static_cast<int>(to_double(value(), "repeat")));
        else if (a == "--seconds") o.seconds = to_double(value(), "seconds");
        else if (a == "--steps") o.steps = std::max(1, static_cast<int>(to_double(value(), "steps")));
        else if (a == "--min-steps") o.min_steps = std::max(1, static_cast<int>(to_double(value(), "min-steps")));
        else if (a == "--warmup") o.warmup = std::max(0, static_cast<int>(to_double(value(), "warmup")));
        else if (a == "--tau") o.tau = to_double(value(), "tau");
        else if (a == "--cases") {
            o.cases.clear();
            std::stringstream ss(value());
            for (std::string item; std::getline(ss, item, ',');) {
                if (item != "mcf" && item != "sphere" && item != "sd") {
                    std::fprintf(stderr, "froth_bench_step: unknown case '%s'\n", item.c_str());
                    usage(2);
                }
                o.cases.push_back(item);
            }
        }
        else {
            std::fprintf(stderr, "froth_bench_step: unknown argument '%s'\n", a.c_str());
            usage(2);
        }
    }
    if (o.quick) {
        if (!sizes_given) o.sizes = {0.15};
        else o.sizes.resize(1);
        o.warmup = 0;
        o.repeat = 1;
        o.steps = 2;
    }
    return o;
}

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

double mean_radius(const froth::Cluster& c) {
    double sum = 0;
    for (const auto& x : c.positions()) sum += x.norm();
    return sum / c.n_vertices();
}

Row run_case(const Case& cs, double h, const Options& o) {
    Row row;
    row.flow = froth::flow_name(cs.flow);
    row.scene = cs.scene == Scene::Sphere ? "sphere" : "double bubble";
    row.h = h;

    auto t0 = Clock::now();
    froth::ClusterSpec spec = cs.scene == Scene::Sphere
                                  ? froth::build_sphere({.R = 1.0, .h = h})
                                  : froth::build_double_bubble({.h = h});
    froth::Cluster c(std::move(spec));
    row.build_s = seconds_since(t0);
    row.vertices = c.n_vertices();
    std::fprintf(stderr, "%s on the %s, h = %g: %d vertices (gmsh %.1f s)\n", row.flow.c_str(),
                 row.scene.c_str(), h, row.vertices, row.build_s);

    froth::TimeStepper stepper;
    // The tables in docs/benchmarks.md time the seed's linear step (one solve); the volume-exact
    // default costs 2-4 (measured in numerics.md, "Volume-exact surface diffusion").
    stepper.set_exact_volumes(false);
    double max_energy_change = -std::numeric_limits<double>::infinity();
    double last_volume_loss = 0;
    int refactors = 0, iterations = 0;
    auto step = [&](double* assemble, double* solve) {
        const auto ts = Clock::now();
        const froth::StepReport r = stepper.step(c, cs.flow, o.tau);
        const double wall = seconds_since(ts);
        if (assemble) *assemble += r.assemble_seconds;
        if (solve) *solve += r.solve_seconds;
        row.unknowns = r.unknowns;
        refactors += r.refactorized ? 1 : 0;
        iterations += r.solver_iterations;
        max_energy_change =
            std::max(max_energy_change, (r.energy - r.energy_before) / r.energy_before);
        last_volume_loss = std::max(last_volume_loss, r.volume_loss);
        return wall;
    };

    row.first_s = step(nullptr, nullptr);
    double last = row.first_s; // then the mean warm-up step
    if (o.warmup > 0) {
        double sum = 0;
        for (int i = 0; i < o.warmup; ++i) sum += step(nullptr, nullptr);
        last = sum / o.warmup;
    }

    int n = o.steps;
    if (n <= 0) n = std::clamp(static_cast<int>(std::ceil(o.seconds / last)), o.min_steps, 1000);
    if (cs.flow == Flow::MeanCurvature && o.steps <= 0) {
        // MCF shrinks both scenes to a point (the unit sphere at t = 1/4): stay below
        // t = kMcfTime, so small meshes get shorter blocks rather than a collapsed cluster.
        const int left = static_cast<int>(kMcfTime / o.tau) - 1 - o.warmup;
        n = std::max(1, std::min(n, left / o.repeat));
    }
    row.steps = n;
    row.blocks = o.repeat;
    row.per_step = std::numeric_limits<double>::infinity();
    double total_wall = 0;
    int total_refactors = 0, total_iterations = 0;
    for (int b = 0; b < o.repeat; ++b) {
        double wall = 0, assemble = 0, solve = 0;
        refactors = iterations = 0;
        for (int i = 0; i < n; ++i) wall += step(&assemble, &solve);
        if (wall / n < row.per_step) {
            row.per_step = wall / n;
            row.solve_share = solve / wall;
            row.assemble_share = assemble / wall;
        }
        total_wall += wall;
        total_refactors += refactors;
        total_iterations += iterations;
        std::fprintf(stderr, "  block %d: %d steps, %.4f s/step, %d refactorisations, %d GMRES "
                     "iterations\n", b + 1, n, wall / n, refactors, iterations);
    }
    row.mean_per_step = total_wall / (n * o.repeat);
    row.refactorizations = total_refactors;
    row.iterations = static_cast<double>(total_iterations) / (n * o.repeat);

    row.t = c.time();
    if (cs.scene == Scene::Sphere) {
        const double R = mean_radius(c);
        const double err = std::abs(R * R - (1.0 - 4.0 * c.time()));
        row.check = "R^2 err " + fmt("%.1e", err);
        row.ok = err < kSphereTol;
    } else if (cs.flow == Flow::SurfaceDiffusion) {
        row.check = "vol loss " + fmt("%.1e", last_volume_loss);
        row.ok = last_volume_loss < kVolumeTol;
    } else {
        row.check = "max dE/E " + fmt("%+.1e", max_energy_change);
        row.ok = max_energy_change < kEnergyTol;
    }
    if (!row.ok) row.check += " FAIL";
    return row;
}

void print_table(const std::vector<Row>& rows) {
    std::vector<std::vector<std::string>> cells;
    cells.push_back({"flow", "scene", "h", "vertices", "unknowns", "first step s", "s/step",
                     "solve", "assembly", "steps/s", "mean s/step", "steps", "refact", "GMRES it",
                     "t", "check at t"});
    for (const Row& r : rows)
        cells.push_back({r.flow, r.scene, fmt("%g", r.h), std::to_string(r.vertices),
                         std::to_string(r.unknowns), fmt("%.3f", r.first_s),
                         fmt("%.4f", r.per_step), fmt("%.0f%%", 100 * r.solve_share),
                         fmt("%.0f%%", 100 * r.assemble_share), fmt("%.2f", 1 / r.per_step),
                         fmt("%.4f", r.mean_per_step),
                         std::to_string(r.blocks) + "x" + std::to_string(r.steps),
                         std::to_string(r.refactorizations),
                         fmt("%.1f", r.iterations), fmt("%.3g", r.t), r.check});
    std::vector<size_t> width(cells[0].size(), 0);
    for (const auto& line : cells)
        for (size_t j = 0; j < line.size(); ++j) width[j] = std::max(width[j], line[j].size());
    auto print_line = [&](const std::vector<std::string>& line) {
        std::printf("|");
        for (size_t j = 0; j < line.size(); ++j) {
            const bool left = j < 2 || j + 1 == line.size();
            std::printf(left ? " %-*s |" : " %*s |", static_cast<int>(width[j]), line[j].c_str());
        }
        std::printf("\n");
    };
    print_line(cells[0]);
    std::printf("|");
    for (size_t j = 0; j < width.size(); ++j) {
        const bool left = j < 2 || j + 1 == width.size();
        std::printf("%s%s|", std::string(width[j] + 1, '-').c_str(), left ? "-" : ":");
    }
    std::printf("\n");
    for (size_t i = 1; i < cells.size(); ++i) print_line(cells[i]);
}

} // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    const char* blas_env = std::getenv("OPENBLAS_NUM_THREADS");
    std::printf("froth_bench_step: %s build, tau = %g, %s, best of %d block%s\n", FROTH_BUILD_TYPE,
                o.tau, blas_env ? ("OPENBLAS_NUM_THREADS=" + std::string(blas_env)).c_str()
                                : "OpenBLAS forced to 1 thread",
                o.repeat, o.repeat == 1 ? "" : "s");
    std::printf("solve/assembly: shares of the wall time of TimeStepper::step; "
                "first step includes the symbolic analysis\n\n");
    std::fflush(stdout);

    std::vector<Row> rows;
    bool ok = true;
    for (const std::string& name : o.cases) {
        const Case cs = name == "sd"       ? Case{Flow::SurfaceDiffusion, Scene::DoubleBubble}
                        : name == "sphere" ? Case{Flow::MeanCurvature, Scene::Sphere}
                                           : Case{Flow::MeanCurvature, Scene::DoubleBubble};
        for (double h : o.sizes) {
            try {
                rows.push_back(run_case(cs, h, o));
                ok = ok && rows.back().ok;
            } catch (const std::exception& e) {
                std::fprintf(stderr, "froth_bench_step: %s, h = %g: %s\n",
                             froth::flow_name(cs.flow), h, e.what());
                ok = false;
            }
        }
    }
    print_table(rows);
    if (!ok) std::printf("\nFAILED: a check is out of bounds (sphere %g, volume %g, energy %g)\n",
                         kSphereTol, kVolumeTol, kEnergyTol);
    return ok ? 0 : 1;
}
