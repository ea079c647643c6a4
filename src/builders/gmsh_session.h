#pragma once
/// Private to the builders (includes gmsh): the gmsh session guard and the mesh extraction that
/// every gmsh builder shares (docs: ../shared/docs/dependencies.md §3).

#include "core/errors.h"
#include "mesh/cluster.h"
#include "mesh/orient_parts.h"

#include <gmsh.h>

#include <array>
#include <cstddef>
#include <mutex>
#include <new>
#include <string>
#include <vector>

namespace froth::gmsh_detail {


/// One froth surface to be: the gmsh surface entities merged into it.
struct FilmPlan {
    std::vector<int> entities;
    double sigma = 1.0;
};

/// A number as the messages print it ("0.05", "1e-05").
std::string num(double x);

// gmsh is a process-wide singleton and not thread-safe, so one session at a time. The guard
// also finalizes when an exception leaves a build half done, so the next build starts clean.
class Session {
  public:
    Session();
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

  private:
    static std::mutex& mutex();
    std::lock_guard<std::mutex> lock_;
};

// gmsh::initialize sets General.AbortOnError = 2, so in 4.8 every gmsh error is thrown as a
// plain std::string (not a std::exception). Runs body in a gmsh session and turns whatever
// gmsh throws into the froth exception E, with prefix naming the operation.
template <class E, class F> auto in_session(const std::string& prefix, F&& body) {
    try {
        Session session;
        return body();
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::string& s) {
        throw E(prefix + s);
    } catch (const std::exception& e) { // anything else (a Lua error) passes through
        throw E(prefix + e.what());
    }
}

/// The 3-node triangles of surface entity tag.
std::vector<NodeTri> entity_triangles(int tag);

/// The ClusterSpec of the current gmsh model: one surface per film (its entities merged and
/// oriented consistently), vertices compacted to the nodes the triangles use, numbered 0.. in
/// increasing gmsh node tag. `bodies` are 0-based film indices.
ClusterSpec extract(const std::vector<FilmPlan>& films, std::vector<std::vector<int>> bodies,
                    const std::string& op);

/// Sorted upward (up) or downward adjacencies of entity (dim, tag).
std::vector<int> adjacent(int dim, int tag, bool up);

/// Sorted tags of every entity of dimension dim.
std::vector<int> entity_tags(int dim);

/// Frontal-Delaunay surface mesh (no tetrahedra) with target edge length at most h.
void mesh_surfaces(double h);

/// Vertex count estimate of a surface mesh of the given area at edge length h: about
/// 1.2 A / h^2 (dependencies.md §3).
double estimated_vertices(double area, double h);

/// h bounds scale with the size of the object; the minimum keeps the mesh below ~1e6 vertices.
/// \throw InvalidInput naming op.
void check_h(const std::string& op, double h, double lo, double hi, double area);

} // namespace froth::gmsh_detail
