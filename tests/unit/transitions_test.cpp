// Topological transitions (mesh/transitions.h): the pop of a vanishing cell; the splits
// before a T1 that would empty a film; the runs' memory of them in a state file.
#include "core/errors.h"
#include "expect_error.h"
#include "geometry/geometry.h"
#include "mesh/transition_surgery.h"
#include "mesh/transitions.h"
#include "run/evolve.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>

namespace froth {
namespace {

/// A bubble of radius r inside one of radius 1: body 1 the shell between them, body 2 the
/// inner ball; surface 1 the outer sphere, surface 2 the inner one.
ClusterSpec nested_spheres(double r) {
    ClusterSpec s = test::icosphere(2, 1.0);
    const ClusterSpec inner = test::icosphere(1, r);
    const int n = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), inner.vertices.begin(), inner.vertices.end());
    ClusterSpec::Surface in = inner.surfaces[0];
    for (Tri& t : in.triangles)
        for (int& v : t) v += n;
    s.surfaces.push_back(in);
    s.bodies = {{0, 1}, {1}};
    return s;
}

void expect_topology_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
    test::expect_error<TopologyError>(f, parts);
}

// One neighbouring cell: the inner bubble goes without a trace, the shell becomes the ball.
TEST(PopBody, BubbleInsideACellLeavesNothing) {
    const Cluster c(nested_spheres(0.3));
    const double shell = body_volumes(c)[0];
    TransitionRecord record;
    const Cluster r = pop_body(c, 1, &record);
    EXPECT_EQ(record.kind, "pop body");
    EXPECT_EQ(record.body, 1);
    EXPECT_EQ(record.neighbours, 1);
    EXPECT_NE(record.where.find("body 2"), std::string::npos);
    EXPECT_EQ(r.n_bodies(), 1);
    EXPECT_EQ(r.n_surfaces(), 1);
    EXPECT_EQ(r.n_vertices(), c.n_vertices() - 42);     // the inner icosphere's 42, and no P
    EXPECT_EQ(record.removed_vertices, 42);
    EXPECT_EQ(record.removed_facets, 80);
    EXPECT_LT((record.point).norm(), 1e-12);             // the inner sphere's centre
    // The shell takes the bubble's volume; its reference stays, its target is the new volume.
    const double ball = body_volumes(r)[0];
    EXPECT_NEAR(ball, shell + body_volumes(c)[1], 1e-12);
    EXPECT_DOUBLE_EQ(r.initial_volumes()[0], c.initial_volumes()[0]);
    EXPECT_DOUBLE_EQ(r.target_volumes()[0], ball);
    // The energy is the outer sphere's alone.
    EXPECT_NEAR(energy(r), energy(Cluster(test::icosphere(2, 1.0))), 1e-12);
    EXPECT_LT(energy(r), energy(c));
    // The old cluster is untouched.
    EXPECT_EQ(c.n_bodies(), 2);
}

TEST(PopBody, KeepsTensionsTimeAndLaterBodiesShiftDown) {
    ClusterSpec s = nested_spheres(0.3);
    s.surfaces[0].sigma = 2.5;
    s.bodies = {{1}, {0, 1}}; // the inner ball first this time
    Cluster c(std::move(s));
    c.set_time(0.75);
    const Cluster r = pop_body(c, 0);
    ASSERT_EQ(r.n_bodies(), 1);
    EXPECT_DOUBLE_EQ(r.surface(0).sigma, 2.5);
    EXPECT_DOUBLE_EQ(r.time(), 0.75);
    EXPECT_DOUBLE_EQ(r.initial_volumes()[0], c.initial_volumes()[1]);
}

TEST(PopBody, RefusesWhatCannotPop) {
    const Cluster sphere(test::icosphere(1));
    expect_topology_error([&] { pop_body(sphere, 0); }, {"body 1", "all the cluster has"});
    test::expect_invalid([&] { pop_body(sphere, 1); }, {"body 2", "does not exist"});
    test::expect_invalid([&] { pop_body(sphere, -1); }, {"body 0", "does not exist"});
    // The shell around the inner bubble has two neighbours' worth of films but its collapse
    // would take the inner bubble's films with it.
    const Cluster nested(nested_spheres(0.3));
    expect_topology_error([&] { pop_body(nested, 0); }, {"body 1"});
    // Collapsing one of two tetrahedra leaves the other without films.
    const Cluster twins(test::twin_tetrahedra());
    expect_topology_error([&] { pop_body(twins, 0); }, {"body 1", "body 2", "without films"});
}

TEST(PopBody, RefusesFixedVertices) {
    ClusterSpec s = nested_spheres(0.3);
    s.fixed = {static_cast<int>(s.vertices.size()) - 1}; // a vertex of the inner bubble
    const Cluster c(std::move(s));
    expect_topology_error([&] { pop_body(c, 1); }, {"body 2", "fixed vertex"});
}

} // namespace
} // namespace froth

namespace froth {
namespace {

/// Four cells around a tetrahedron's centre (vertex 4): the inner film between cells i and j
/// has the facets (4, 5 + i, 5 + j), (5 + i, i, j), (5 + i, j, 5 + j), vertex 5 + i being the
/// first vertex of the line from the centre to corner i; each cell's outer face is a film
/// of one facet between three corners, all of them quadruple points (with the outside).
ClusterSpec four_cells() {
    ClusterSpec s;
    s.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}, {0, 0, 0}};
    const Vec3 bend[4] = {{0.1, -0.05, 0}, {0, 0.1, -0.05}, {-0.05, 0, 0.1}, {0.1, 0, -0.05}};
    for (int i = 0; i < 4; ++i) s.vertices.push_back(0.5 * s.vertices[i] + bend[i]);
    int film[4][4];
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            film[i][j] = static_cast<int>(s.surfaces.size());
            s.surfaces.push_back({{{4, 5 + i, 5 + j}, {5 + i, i, j}, {5 + i, j, 5 + j}}, 1.0});
        }
    for (int k = 0; k < 4; ++k) { // the cell opposite corner k
        std::vector<int> o;
        for (int i = 0; i < 4; ++i)
            if (i != k) o.push_back(i);
        s.surfaces.push_back({{{o[0], o[1], o[2]}}, 1.0});
        s.bodies.push_back({static_cast<int>(s.surfaces.size()) - 1, film[o[0]][o[1]],
                            film[o[0]][o[2]], film[o[1]][o[2]]});
    }
    return s;
}

int line_between(const Cluster& c, int a, int b) {
    for (std::size_t l = 0; l < c.triple_lines().size(); ++l) {
        const std::vector<int>& v = c.triple_lines()[l].vertices;
        if (v.size() == 2u && std::min(v[0], v[1]) == std::min(a, b) &&
            std::max(v[0], v[1]) == std::max(a, b))
            return static_cast<int>(l);
    }
    return -1;
}

// The line between corners 1 and 2 is a side of the outer faces of the cells opposite corners
// 0 and 3 (surfaces 6 and 9), films of one facet that its T1 would leave without one: their
// two other sides are split at their midpoints (each a side of another outer face too, so
// all four get three facets), nothing else changes (areas and volumes exactly).
TEST(SplitFilmsEmptiedByT1, SplitsTheOtherSidesOfAOneFacetFilm) {
    const Cluster c(four_cells());
    const int line = line_between(c, 1, 2);
    ASSERT_GE(line, 0);
    const std::optional<Cluster> r = split_films_emptied_by_t1(c, line);
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r->n_vertices(), c.n_vertices() + 4); // corners 0-1, 0-2, 3-1, 3-2
    for (int v = 0; v < c.n_vertices(); ++v) EXPECT_EQ(r->position(v), c.position(v));
    for (int face = 6; face < 10; ++face) {
        EXPECT_EQ(c.surface(face).triangles.size(), 1u);
        EXPECT_EQ(r->surface(face).triangles.size(), 3u);
    }
    EXPECT_EQ(r->triple_lines().size(), c.triple_lines().size());
    EXPECT_EQ(r->quadruple_points(), c.quadruple_points());
    EXPECT_NEAR(energy(*r), energy(c), 1e-13);
    const std::vector<double> before = body_volumes(c), after = body_volumes(*r);
    for (std::size_t b = 0; b < before.size(); ++b) EXPECT_NEAR(after[b], before[b], 1e-14);
    EXPECT_NE(line_between(*r, 1, 2), -1); // the line itself is not split
}

// A line from the centre has no such film (the inner films have a facet with one corner on
// it): nothing to split.
TEST(SplitFilmsEmptiedByT1, NothingWhereEveryFilmKeepsAFacet) {
    const Cluster c(four_cells());
    for (std::size_t l = 0; l < c.triple_lines().size(); ++l)
        if (c.triple_lines()[l].vertices.size() == 3u)
            EXPECT_FALSE(split_films_emptied_by_t1(c, static_cast<int>(l)).has_value());
}

/// four_cells with the film between the lines to corners 1 and 2 (surface 4) triangulated
/// anew around a vertex x (9) beside the line to corner 1: x is joined to the line's three
/// vertices (4, 6, 1), and vertex 7 of the other line to its two ends only. Collapsing the
/// line to a point would give that film two facets (x, 7) and (7, x) at it: a fold (the
/// 200-grain network's stop at t = 1.540 had this shape).
ClusterSpec four_cells_with_a_fold() {
    ClusterSpec s = four_cells();
    const Vec3 x = 0.5 * s.vertices[6] + 0.3 * s.vertices[1] + 0.2 * s.vertices[7];
    s.vertices.push_back(x);
    s.surfaces[3].triangles = {{4, 6, 9}, {6, 1, 9}, {9, 1, 7}, {1, 2, 7}, {9, 7, 4}};
    return s;
}

int line_through(const Cluster& c, int v) {
    for (std::size_t l = 0; l < c.triple_lines().size(); ++l) {
        const std::vector<int>& w = c.triple_lines()[l].vertices;
        if (std::find(w.begin(), w.end(), v) != w.end()) return static_cast<int>(l);
    }
    return -1;
}

// Without the splits the T1 is refused ("fold"); with part_common_neighbours the edges from
// vertex 7 to the line's ends are split, which changes no area or volume, and the T1 goes.
TEST(SplitFilmsEmptiedByT1, PartsAFilmThatWouldFoldOverTheLine) {
    const Cluster c(four_cells_with_a_fold());
    const int line = line_through(c, 6);
    ASSERT_GE(line, 0);
    ASSERT_EQ(c.triple_lines()[line].vertices.size(), 3u);
    test::expect_error<TopologyError>([&] { t1_line_to_film(c, line, nullptr, 0, 0, false); },
                                      {"would fold surface 4 over the point"});
    EXPECT_FALSE(split_films_emptied_by_t1(c, line).has_value());
    const std::optional<Cluster> r = split_films_emptied_by_t1(c, line, true);
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r->n_vertices(), c.n_vertices() + 2); // on the edges (1, 7) and (4, 7)
    for (int v = 0; v < c.n_vertices(); ++v) EXPECT_EQ(r->position(v), c.position(v));
    const Vec3 mid_1 = 0.5 * (c.position(1) + c.position(7));
    const Vec3 mid_4 = 0.5 * (c.position(4) + c.position(7));
    for (int v = c.n_vertices(); v < r->n_vertices(); ++v)
        EXPECT_LT(std::min((r->position(v) - mid_1).norm(), (r->position(v) - mid_4).norm()),
                  1e-15);
    EXPECT_NE((r->position(c.n_vertices()) - r->position(c.n_vertices() + 1)).norm(), 0.0);
    EXPECT_NEAR(energy(*r), energy(c), 1e-13);
    const std::vector<double> before = body_volumes(c), after = body_volumes(*r);
    for (std::size_t b = 0; b < before.size(); ++b) EXPECT_NEAR(after[b], before[b], 1e-14);
    // the T1 itself: the line becomes a film, its three corners quadruple points
    const Cluster t1 = t1_line_to_film(c, line);
    EXPECT_EQ(t1.quadruple_points().size(), c.quadruple_points().size() + 1);
    EXPECT_EQ(t1.n_surfaces(), c.n_surfaces() + 1);
}

int line_with_vertices(const Cluster& c, const std::vector<int>& vertices) {
    for (std::size_t l = 0; l < c.triple_lines().size(); ++l)
        if (c.triple_lines()[l].vertices == vertices) return static_cast<int>(l);
    return -1;
}

// The T1 of the line between corners 0 and 2 of four_cells, then that of the line 1-6-2 of
// the result, leave film 6 a triangle (corners 8, 9, 13) with the first T1's film (surface 11,
// one facet, 8-9-10) on its side 8-9: the 200-grain network's stop at t = 1.044, where an
// inverse T1 would have left the film a T1 had just made without a facet. Its sides off the
// line are split first (2 new vertices, 3 facets; nothing else changes), and the inverse T1
// goes; without the splits it failed ("surface 10 has no facets": the film beside, numbered
// after the collapsed film went).
TEST(SplitFilmsEmptiedByCollapse, SplitsAOneFacetFilmBesideAnInverseT1) {
    const Cluster c0(four_cells());
    const Cluster c1 = t1_line_to_film(c0, line_between(c0, 0, 2));
    const int second = line_with_vertices(c1, {1, 6, 2});
    ASSERT_GE(second, 0);
    const Cluster c = t1_line_to_film(c1, second);
    const int film = 5, beside = 10;
    ASSERT_EQ(c.surface(beside).triangles.size(), 1u);
    int sides = 0;
    for (const TripleLine& l : c.triple_lines())
        sides += static_cast<int>(std::count(l.surfaces.begin(), l.surfaces.end(), film));
    ASSERT_EQ(sides, 3);

    const std::optional<Cluster> r = split_films_emptied_by_collapse(c, film);
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(r->n_vertices(), c.n_vertices() + 2);
    for (int v = 0; v < c.n_vertices(); ++v) EXPECT_EQ(r->position(v), c.position(v));
    EXPECT_EQ(r->surface(beside).triangles.size(), 3u);
    EXPECT_EQ(r->surface(film).triangles, c.surface(film).triangles);
    EXPECT_EQ(r->quadruple_points(), c.quadruple_points());
    EXPECT_NEAR(energy(*r), energy(c), 1e-13);
    const std::vector<double> before = body_volumes(c), after = body_volumes(*r);
    for (std::size_t b = 0; b < before.size(); ++b) EXPECT_NEAR(after[b], before[b], 1e-14);
    // the second T1's film (11 12 13): every film along it keeps a facet off its side
    EXPECT_FALSE(split_films_emptied_by_collapse(c, 11).has_value());

    TransitionRecord record;
    const Cluster t = t1_film_to_line(c, film, &record);
    EXPECT_EQ(record.kind, "inverse T1");
    EXPECT_EQ(t.n_surfaces(), c.n_surfaces() - 1);
    EXPECT_EQ(t.surface(beside - 1).triangles.size(), 2u); // the facet on the line went
    // its three corners go, the two ends of the new line come
    EXPECT_EQ(t.quadruple_points().size(), c.quadruple_points().size() - 1);
}

} // namespace
} // namespace froth

namespace froth {
namespace {

double shortest_edge(const Cluster& c) {
    double shortest = INFINITY;
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(c.positions(), f);
            for (int k = 0; k < 3; ++k) shortest = std::min(shortest, (x[(k + 1) % 3] - x[k]).norm());
        }
    return shortest;
}

// A film vertex pushed to 1e-3 from a neighbour: relax_short_edge_ends moves it (or the
// neighbour) in its tangent plane to its neighbours' mean, the edge opens to the mesh's size.
TEST(RelaxShortEdgeEnds, OpensAShortEdge) {
    ClusterSpec s = test::icosphere(2, 1.0);
    s.bodies = {{0}};
    // the lower id moves (the first of the pass): the one pushed next to the other
    const Tri t = s.surfaces[0].triangles[0];
    const int pushed = std::min(t[0], t[1]), other = std::max(t[0], t[1]);
    const Vec3 a = s.vertices[pushed], b = s.vertices[other];
    s.vertices[pushed] = b + 1e-3 * (a - b).normalized();
    const Cluster c(s);
    EXPECT_NEAR(shortest_edge(c), 1e-3, 1e-12);
    EXPECT_FALSE(relax_short_edge_ends(c, 1e-4).cluster.has_value()); // none that short
    const VertexRelaxResult r = relax_short_edge_ends(c, 1e-2);
    ASSERT_TRUE(r.cluster.has_value());
    EXPECT_EQ(r.moved, 1); // the two ends are neighbours: one moves
    EXPECT_EQ(r.cluster->position(other), c.position(other));
    EXPECT_GT(shortest_edge(*r.cluster), 0.1);
    EXPECT_NEAR(body_volumes(*r.cluster)[0], body_volumes(c)[0], 1e-3 * body_volumes(c)[0]);
}

} // namespace
} // namespace froth

namespace froth {
namespace {

// The four cells refined once: every film gets vertices inside. remesh_thin_films with a
// width above every film's takes them all out and triangulates each film's border alone
// (n border vertices, n - 2 facets); the lines and quadruple points stay. With a width below
// every film's nothing changes.
TEST(RemeshThinFilms, TriangulatesTheBorderAlone) {
    const Cluster c = refine(Cluster(four_cells()));
    const std::vector<int> rank = [&] {
        std::vector<int> on_junction(c.n_vertices(), 0);
        for (const JunctionEdge& e : c.junction_edges()) on_junction[e.a] = on_junction[e.b] = 1;
        return on_junction;
    }();
    const int junction_vertices = static_cast<int>(std::count(rank.begin(), rank.end(), 1));
    ASSERT_LT(junction_vertices, c.n_vertices()); // film vertices inside
    EXPECT_FALSE(remesh_thin_films(c, 1e-6).cluster.has_value());
    const EdgeCollapseResult r = remesh_thin_films(c, 10.0);
    ASSERT_TRUE(r.cluster.has_value());
    const Cluster& d = *r.cluster;
    EXPECT_EQ(d.n_vertices(), junction_vertices);
    EXPECT_EQ(r.collapsed, c.n_vertices() - junction_vertices);
    EXPECT_EQ(d.triple_lines().size(), c.triple_lines().size());
    EXPECT_EQ(d.quadruple_points().size(), c.quadruple_points().size());
    for (int si = 0; si < d.n_surfaces(); ++si) {
        std::set<int> border;
        for (const Tri& t : d.surface(si).triangles) border.insert(t.begin(), t.end());
        EXPECT_EQ(d.surface(si).triangles.size(), border.size() - 2) << "surface " << si;
    }
    // the cells keep their volumes to within the films' bends
    const std::vector<double> before = body_volumes(c), after = body_volumes(d);
    for (std::size_t b = 0; b < before.size(); ++b) EXPECT_NEAR(after[b], before[b], 0.05 * before[b]);
}

} // namespace
} // namespace froth

namespace froth {
namespace {

/// A fan of four facets in the plane z = 0 around the vertex 4 (moved to p), their far
/// corners the square's corners (+-1, 0), (0, +-1); the facets' old area vectors face +z.
struct Fan {
    ClusterSpec spec;
    std::vector<surgery::MovedFacet> moved;
    std::vector<Vec3> V;
};

Fan square_fan(const Vec3& p) {
    Fan f;
    f.V = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, p};
    ClusterSpec::Surface s;
    for (int k = 0; k < 4; ++k) s.triangles.push_back({4, k, (k + 1) % 4});
    f.spec.surfaces.push_back(s);
    for (int k = 0; k < 4; ++k) f.moved.push_back({0, k, Vec3(0, 0, 1)});
    return f;
}

// A corner outside the square's kernel turns facets; fit_corners brings it back inside with
// a hundredth of each edge's length to spare, and no facet turns.
TEST(FitCorners, MovesACornerOffTheSlivers) {
    Fan f = square_fan({0.9, 0.9, 0.2});
    ASSERT_TRUE(surgery::turns_a_facet(f.spec, f.V, f.moved));
    ASSERT_TRUE(surgery::fit_corners(f.spec, f.V, f.moved, {4}, 2.0));
    EXPECT_FALSE(surgery::turns_a_facet(f.spec, f.V, f.moved));
    // its distance to the nearest side of the square (|x| + |y| = 1) is at least a hundredth
    // of that side's length, sqrt(2)
    const Vec3 p = f.V[4];
    const double to_side = (1 - std::abs(p.x()) - std::abs(p.y())) / std::sqrt(2.0);
    EXPECT_GE(to_side, 0.01 * std::sqrt(2.0) - 1e-12);
    EXPECT_NEAR(p.z(), 0.2, 1e-12); // moves stay in the facets' planes
}

// A corner that already keeps every facet stays where it is; one that would need to move
// further than max_shift is refused.
TEST(FitCorners, KeepsAGoodCornerAndRefusesAFarOne) {
    Fan good = square_fan({0.1, -0.2, 0});
    ASSERT_TRUE(surgery::fit_corners(good.spec, good.V, good.moved, {4}, 0.0));
    EXPECT_EQ(good.V[4], Vec3(0.1, -0.2, 0));
    Fan far = square_fan({3, 3, 0});
    EXPECT_FALSE(surgery::fit_corners(far.spec, far.V, far.moved, {4}, 1.0));
}

/// A transition memory as a state file holds it, for a cluster of 2 bodies (1-based, 0 the
/// outside): a line and a triangular film with their sizes, a product not yet measured, a
/// contact two looks old and a film's waist.
std::vector<NamedValues> saved_memory() {
    return {{"junctions.scalars", {0.2, 1, 2, 7}},
            {"junctions.line_sizes", {5, 0, 1, 2, 0, 1, 0.04}},
            {"junctions.film_sizes", {5, 1, 2, 0, 1, 2, 0.3, 5, 2, 2, 0, 1, 2, 0.25}},
            {"junctions.line_products", {5, 0, 1, 2, 0, 1, -1}},
            {"junctions.film_products", {}},
            {"junctions.contacts", {2, 1, 2, 5}},
            {"junctions.waist_sizes", {4, 1, 2, 0, 1, 0.01}},
            {"transitions.run", {0.31, 1, 0.5}}};
}

TEST(TransitionMemory, ReadsBackWhatItWrites) {
    const Cluster c(nested_spheres(0.4)); // only its number of bodies counts
    ASSERT_EQ(c.n_bodies(), 2);
    const std::vector<NamedValues> saved = saved_memory();
    const TransitionMemory m = restore_transition_memory(saved, c);
    ASSERT_TRUE(m.junctions.has_value());
    EXPECT_EQ(m.longest_edge, 0.31);
    EXPECT_TRUE(m.transitions_made);
    EXPECT_EQ(m.tau_scale, 0.5);
    EXPECT_TRUE(m.junctions->fits(2, 0.2));
    const std::vector<NamedValues> again = save_transition_memory(m);
    ASSERT_EQ(again.size(), saved.size());
    for (std::size_t k = 0; k < saved.size(); ++k) {
        EXPECT_EQ(again[k].name, saved[k].name);
        EXPECT_EQ(again[k].values, saved[k].values) << saved[k].name;
    }
    EXPECT_FALSE(restore_transition_memory({}, c).junctions.has_value()); // a format 3 file
}

/// Every value of a saved memory replaced by hostile ones, and every array cut short: each is
/// read or refused with InvalidInput naming the array, never anything else (run under ASan in
/// CI, so a bad read aborts).
TEST(TransitionMemory, RefusesDamagedArraysByName) {
    const Cluster c(nested_spheres(0.4));
    ASSERT_TRUE(restore_transition_memory(saved_memory(), c).junctions.has_value());
    const double hostile[] = {std::numeric_limits<double>::quiet_NaN(), INFINITY, -INFINITY, -2,
                              -1, 0, 0.5, 3, 6, 1e9, 1e300};
    int refused = 0, read = 0;
    const auto attempt = [&](const std::vector<NamedValues>& arrays) {
        try {
            restore_transition_memory(arrays, c);
            ++read;
        } catch (const InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("transition memory: "), std::string::npos);
            ++refused;
        }
    };
    for (std::size_t a = 0; a < saved_memory().size(); ++a) {
        for (std::size_t i = 0; i < saved_memory()[a].values.size(); ++i)
            for (double x : hostile) {
                std::vector<NamedValues> arrays = saved_memory();
                arrays[a].values[i] = x;
                attempt(arrays);
            }
        std::vector<NamedValues> cut = saved_memory();
        if (!cut[a].values.empty()) cut[a].values.pop_back(), attempt(cut);
        std::vector<NamedValues> without = saved_memory();
        without.erase(without.begin() + static_cast<std::ptrdiff_t>(a));
        attempt(without);
    }
    EXPECT_GT(refused, 100);
    EXPECT_GT(read, 10); // a size of 0.5 or 6 and the like is a valid memory
}

} // namespace
} // namespace froth
