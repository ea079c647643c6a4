#pragma once
/// Geometric quantities of a cluster on its current positions: facet areas and normals,
/// energy, body volumes, lumped masses and weighted normals (numerics.md §2), junction angles
/// and mesh quality. Free functions; nothing is cached.

#include "mesh/cluster.h"

#include <Eigen/SparseCore>

#include <string>
#include <utility>
#include <vector>

namespace froth {

/// Twice the area vector of triangle t: (x1 - x0) x (x2 - x0).
inline Vec3 area_vector2(const std::vector<Vec3>& X, const Tri& t) {
    return (X[t[1]] - X[t[0]]).cross(X[t[2]] - X[t[0]]);
}
/// The same for a facet's corners (Surface::corners: whole also across a periodic box).
inline Vec3 area_vector2(const std::array<Vec3, 3>& x) { return (x[1] - x[0]).cross(x[2] - x[0]); }

/// The first (surface, facet) whose area at positions X is not positive relative to its edges
/// (|x1 - x0| x |x2 - x0| <= 1e-12 (|x1 - x0|^2 + |x2 - x0|^2)), or {-1, -1}.
std::pair<int, int> find_degenerate_facet(const Cluster& c, const std::vector<Vec3>& X);
/// "facet f of surface s" (1-based) for messages.
std::string facet_name(int surface, int facet);

/// Moves every wall-attached vertex of X back onto its walls (alternating projections for a
/// vertex on two): the optional projection of the seed's remark after (3.12).
void project_onto_walls_of(const Cluster& c, std::vector<Vec3>& X);

/// |Gamma_i| for every surface i.
std::vector<double> surface_areas(const Cluster& c);
/// E = sum_i sigma_i |Gamma_i| (seed (1.5) with tensions); with anisotropies
/// E_gamma = sum_i sigma_i int gamma_i(nu), the discrete |Gamma^m|_gamma of (3.21).
double energy(const Cluster& c);
/// Body volumes by the divergence theorem, exact for closed polyhedra (numerics.md §1); a
/// body closed by a wall adds its lids (lid_volume: exact on flat walls).
std::vector<double> body_volumes(const Cluster& c);
/// The same at positions X (one per vertex) instead of the cluster's own.
std::vector<double> body_volumes(const Cluster& c, const std::vector<Vec3>& X);
/// max_b |V_b - V_b(0)| / V_b(0); 0 for a cluster without bodies.
double max_volume_loss(const Cluster& c, const std::vector<double>& volumes);
/// max_b |V_b - V*_b| / V*_b against the target volumes (Cluster::target_volumes); 0 without
/// bodies. What the volume-exact schemes drive to zero.
double max_target_deviation(const Cluster& c, const std::vector<double>& volumes);

/// The gradients of the body volumes with respect to the vertex positions: column b holds
/// d V_b / d X_v in rows 3v..3v+2 (3 n_vertices x n_bodies). Away from lids this is
/// (1/6) sum of the signed area vectors (x_1 - x_0) x (x_2 - x_0) of the body's facets at v, the
/// translation-invariant form that sums to zero over a closed body; at the rim vertices of a
/// lid the films' cone gradients plus the lid's own (lid_volume differentiated by central
/// differences, exact for flat walls, where it is quadratic in the positions).
Eigen::MatrixXd body_volume_gradients(const Cluster& c);
/// The same at positions X (one per vertex) instead of the cluster's own.
Eigen::MatrixXd body_volume_gradients(const Cluster& c, const std::vector<Vec3>& X);
/// The same as a sparse matrix (a body's column is nonzero at its films' vertices only): what
/// foams of many cells need.
Eigen::SparseMatrix<double> sparse_body_volume_gradients(const Cluster& c,
                                                         const std::vector<Vec3>& X);

/// Per (surface, vertex) pair (Cluster::pair_*): lumped mass m_iv = 1/3 sum |sigma| and the
/// area-weighted normal omega_iv = sum |sigma| nu_sigma / sum |sigma| (not normalised).
struct PairGeometry {
    std::vector<double> mass;
    std::vector<Vec3> omega;
    /// Only when some mobility is not 1 (else empty: the isotropic systems use mass):
    /// beta_i(nu_sigma) per surface and facet, and mb_iv = 1/3 sum beta |sigma| (M_beta, §4).
    std::vector<std::vector<double>> facet_beta;
    std::vector<double> mass_beta;
};
PairGeometry pair_geometry(const Cluster& c);
/// m_v = sum_i m_iv over the surfaces at v: the lumped mass of each vertex (its entries sum to
/// the total film area).
Eigen::VectorXd vertex_masses(const Cluster& c, const PairGeometry& g);
/// The unit direction of the triple line through vertex v (either sign), zero at a film vertex
/// or a quadruple point: the eigenvector of the smallest eigenvalue of sum_i m_iv omega_iv
/// omega_iv^T, the direction the normals of the line's films leave free. (They are never
/// exactly coplanar, so the line's direction is not their null space.)
Vec3 line_direction(const Cluster& c, const PairGeometry& g, int v);

struct AngleStats {
    double min = 0, max = 0, mean = 0; ///< degrees
    int count = 0;
    /// Film angles only: the largest deviation (degrees) from the angles Young's law predicts
    /// for the tensions, cos theta_jk = (sigma_i^2 - sigma_j^2 - sigma_k^2) / (2 sigma_j sigma_k)
    /// (force balance sum_j sigma_j mu_j = 0); NaN if some tensions admit no balance.
    /// Isotropic only: with anisotropies use force_imbalance.
    double young_error = 0;
    /// Contact angles: the largest relative residual of (1.26b), see contact_angles.
    /// Film angles: the largest relative force imbalance of (2.3), the anisotropic
    /// (Cahn–Hoffmann, Herring) force balance sum_j Pi_T gamma_j'(nu_j) = 0 with gamma_j =
    /// sigma_j gamma_j and the normals nu_j = t x mu_j consistently oriented:
    /// |sum_j Pi_T gamma_j'(nu_j)| / sum_j |Pi_T gamma_j'(nu_j)| over the line vertices, with
    /// the fitted film directions mu_j. 0 at equilibrium up to the fits' error; for isotropic
    /// films |sum_j sigma_j mu_j| / sum_j sigma_j (1/3 for angles 90/90/180, equal tensions).
    double force_imbalance = 0;
};
/// Angles between the films at the triple lines, three per line vertex (quadruple points and
/// line ends excluded). Each film's direction leaving the line is taken from a quadratic fit of
/// the film over two rings of its vertices, so the measurement is second order in h; the facet
/// chords alone are biased by about h * curvature / 2 (2-3 degrees on the default scene).
AngleStats triple_line_angles(const Cluster& c);

/// The film angles at one line vertex (triple_line_angles gathers them).
struct LineVertexAngles {
    int vertex = -1;
    std::array<int, 3> surfaces{}; ///< the line's surfaces, increasing
    /// angles[i]: the angle (degrees) between the two films other than surfaces[i], the one
    /// that faces film i
    std::array<double, 3> angles{};
    double young_error = 0;     ///< max_i |angles[i] - Young's angle| (NaN: no balance)
    double force_imbalance = 0; ///< of (2.3), as AngleStats::force_imbalance
};
/// The film angles at every line vertex that is neither a quadruple point nor a line end, in
/// vertex order.
std::vector<LineVertexAngles> triple_line_vertex_angles(const Cluster& c);

/// Angles between the triple lines leaving each quadruple point (6 per point with 4 lines;
/// arccos(-1/3) = 109.47 degrees at equilibrium). Line directions from quadratic extrapolation
/// through the next two vertices of each line.
AngleStats quadruple_point_angles(const Cluster& c);

/// Angles between films and walls at the wall-attached vertices: the angle between the film's
/// normal and the wall's normal grad F / |grad F|, 90 degrees where the film meets the wall
/// perpendicularly (the isotropic equilibrium, (1.26b)). The film normal at the wall comes from
/// the same quadratic fit as the film angles (second order in h). count = 0 without walls;
/// young_error = max |angle - 90|; force_imbalance = max |n . gamma'(nu)| / |gamma'(nu)|, the
/// relative residual of the anisotropic contact condition (1.26b) (gamma' = nu for isotropic
/// films: |cos angle|).
AngleStats contact_angles(const Cluster& c);

/// max over wall-attached vertices of the distance |F| / |grad F| to their walls: how far the
/// linearised constraint (3.10)/(3.11) has let vertices drift off curved walls (0 on planes up
/// to round-off).
double wall_drift(const Cluster& c);

struct MeshQuality {
    double min_angle = 0, max_angle = 0; ///< facet corner angles, degrees
    double max_edge_ratio = 0;           ///< longest / shortest edge within a facet
    double min_area = 0;                 ///< smallest facet area
};
MeshQuality mesh_quality(const Cluster& c);

/// Euclidean distance from x to the ellipsoid surface sum_i (y_i / a_i)^2 = 1 (axis-aligned,
/// centered at 0): the closest point is y_i = a_i^2 x_i / (a_i^2 + t) with t the root of
/// sum_i (a_i x_i / (a_i^2 + t))^2 = 1, found by Newton from the right (the function is convex
/// and decreasing there, so the iteration is monotone). The error measure of the seed's Table 1
/// (distance to the exact solution (5.5), "computed by a Newton method").
double distance_to_ellipsoid(const Vec3& x, const Vec3& axes);

/// Per body: what the MacPherson-Srolovitz law of grain growth is written in (mean_width.cpp).
struct GrainMeasures {
    double volume = 0;
    double area = 0;        ///< of the body's boundary
    /// L(D) = (1 / 2 pi) sum over the boundary's mesh edges of |e| alpha_e, alpha_e the
    /// exterior angle between the body's outward facet normals there: (1 / 2 pi) (int kappa dA
    /// + sum over lines of int alpha ds), twice the classical mean breadth (a ball: 4 R)
    double mean_width = 0;
    double line_length = 0; ///< the length of the body's triple lines (edges where its surfaces meet)
};
/// For MCF with normal velocity kappa and 120-degree lines, dV/dt = -2 pi (L - line_length / 6).
std::vector<GrainMeasures> grain_measures(const Cluster& c);

/// Sum of principal curvatures per vertex (positive on a sphere with outward normals), from
/// the discrete Laplacian of the surface with the lowest id at that vertex. For output only.
std::vector<double> vertex_mean_curvature(const Cluster& c);

} // namespace froth
