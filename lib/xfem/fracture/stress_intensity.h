// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/fracture/face_contact_pressure.h"
#include "xfem/integrate/tet_materials.h"

namespace xfem {

/// Stress intensity factors along the cut front by the interaction integral in its 3D domain form
/// (Moran & Shih; Gosz & Moran; the form of MOOSE's DomainIntegral and Abaqus). At a front point
/// P with local frame (a ahead, b the cut's normal, c along the front, crack_front.h):
///
///   I_m(P) = 1/Q * integral over V of [ sigma_ij u^m_i,k a_k + sigma^m_ij u_i,k a_k
///                                       - sigma_kl eps^m_kl a_j ] q_,j dV
///            - 1/Q * integral over V of body_i u^m_i,k a_k q dV,   Q = integral along the front of q ds,
///
/// (q = 1 at the front, falling to 0 outwards; the divergence theorem turns the contour integral
/// around the front into this volume integral, which stays away from the singularity), where u^m
/// is Williams mode m with unit K in the frame of P (exact_fields.h) and u the X-FEM solution. The
/// weight q is the product of a radial ramp and a tangential hat, given at the mesh's nodes and
/// interpolated linearly (so q is continuous and its gradient constant per tet):
///   q_radial(rho) = 1 for rho <= plateau R, falling linearly to 0 at rho = R (rho = distance to
///   the front); q_tangential(s) = max(0, 1 - |s - s_P| / spacing) (s = arc length of the closest
///   front point).
/// Q is the trace of that interpolated q along the front, integrated numerically. Plane strain
/// at an interior front point (the 3D near-front field):
///   I_1 = 2 (1 - nu^2) / E K_I,   I_2 = 2 (1 - nu^2) / E K_II,   I_3 = K_III / mu,
///   G = (1 - nu^2) / E (K_I^2 + K_II^2) + K_III^2 / (2 mu).
/// Exact for a straight front in a homogeneous body with traction-free cut faces when the
/// integrals are exact and the domain stays inside the body (q = 0 on the outer boundary), apart
/// from the ends of an open front, where the domain meets the body's surface: there the surface
/// term + int q [sigma:eps^aux (a.n) - (sigma n).(H a) - (sigma^aux n).(grad u a)] dS over the
/// surface faces with q > 0 is added (FrontSifOptions::surface_term). Signs follow the frame: K_I > 0 opens the
/// cut; K_II, K_III change sign with the cut's normal.
///
/// Curved front (FrontAuxiliary::Curvilinear, the default; Gosz, Dolbow & Moran 1998, Gosz & Moran
/// 2002, Walters, Paulino & Dodds 2005): the Williams fields of the straight tangent line at P
/// put their own crack on the tangent half-plane, which cuts through intact material where the
/// front curves away, and their singular line leaves the front: on a penny-shaped crack K_I comes
/// out 1-4 % high, growing with the hat's width. Instead the front near P is modelled by its
/// osculating circle in the cut's plane at P (curvature kappa, from the turn of the tangent over
/// the hat, signed so that c' = -kappa a; 0 for a straight front), and every point x takes its
/// own toroidal coordinates around it: the foot P(x) on the circle, the frame (a, b, c)(x) there,
/// xa = a(x).(x - P(x)), xb = b.(x - P(x)), h = 1 + kappa xa (grad s = c / h). The auxiliary gradient
/// H is the 2D Williams gradient in that frame (H c = 0), eps^aux = sym H, sigma^aux = C eps^aux:
/// traction-free on the cut's faces and singular on the front, but neither compatible (H is not
/// a gradient) nor in equilibrium (div sigma^aux != 0). With the virtual crack advance
/// q_k = q a_k(x) the divergence theorem gives, exactly (P_kj = sigma:eps^aux delta_kj - sigma_ij H_ik
/// - sigma^aux_ij u_i,k):
///   I Q = -int P_kj a_k q_,j dV - int q (kappa / h) P_cc dV                   (grad a = kappa c c^T / h)
///         + int q (kappa / h) (H_aa sigma_cc - H_ca sigma_ac) dV              (incompatibility)
///         + int q (kappa / h) [(sigma^aux_aa - sigma^aux_cc) u_a,a + sigma^aux_ab u_b,a
///                               + 2 sigma^aux_ac u_c,a] dV                     (non-equilibrium)
///         - int q body_i H_ik a_k dV,
/// components in the frame at x (u_b,a = b . grad u a). The singular parts of the last two cancel
/// analytically (2D compatibility and equilibrium of the Williams fields): what is left is
/// O(kappa r^-1), integrable. On a straight front kappa = 0 and this is the form above.
///
/// Loaded faces (FrontSifOptions::face_pressure, face_traction): the divergence theorem over the
/// domain, whose boundary includes the cut's two faces, leaves on them int q P_kj a_k m_j dA (m the
/// material's outward normal, a.m = 0 on a flat face; the auxiliary field is traction-free there),
/// i.e. - int q t . (H a) dA with t = sigma m the applied traction: summed over the two faces,
///   I Q += - int over the cut of q (p n + t) . [[H a]] dA,   [[H a]] = H a (above) - H a (below),
/// the sign convention of Moes & Gravouil's and Walters, Paulino & Dodds's crack-face term. Only
/// F_0 = sqrt(r) sin(theta / 2) jumps, so [[H a]] ~ rho^-1/2 along the front (crack_face_rule.h).
enum class FrontAuxiliary {
  Curvilinear,             ///< toroidal Williams fields with the curvature terms (default)
  CurvilinearUncorrected,  ///< the same fields without the incompatibility and non-equilibrium terms (for studies)
  Tangent,                 ///< the Williams fields of the straight tangent line at P (before issue 15's fix)
};

struct FrontSifOptions {
  double radius = 0.0;   ///< R, metres; 0: 2.5 x the mean edge length of the partially cut tets
  double plateau = 0.4;  ///< fraction of R where q_radial = 1 (0 <= plateau < 1)
  double spacing = 0.0;  ///< distance between front points and hat half-width, metres; 0: R
  int order = 4;         ///< Gauss points per direction of the conforming rule (conforming_quadrature.h)
  FrontAuxiliary auxiliary = FrontAuxiliary::Curvilinear;
  /// At an end of an open chain (on the body's surface) add the domain form's surface term over the
  /// body's faces where q > 0 (on a free face: -q (sigma^aux n).(grad u a), the plane-strain auxiliary
  /// field not being traction-free there); false: leave it out (before issue 15's second session).
  bool surface_term = true;
  /// Run even when the cost estimate (front_cost.h) exceeds its limits (--allow-large).
  bool allow_large = false;
  /// Each tet's material (problem.json `materials`); null, or one material: E and nu everywhere.
  /// With several, each front point's domain (the tets where q > 0 at a node) must hold tets of
  /// one material, whose E and nu are used there; else xfem::Error naming the point and two regions.
  const TetMaterials* materials = nullptr;
  /// A load on the evaluated cut's faces (problem.json cut_loads on that cut, summed): the face
  /// above (H = +1) pushed by face_pressure n + face_traction, the face below by the opposite. With
  /// either non-zero the crack-face term - 1/Q int over the cut of q (p n + t) . [[H a]] dA is added
  /// (docs/METHOD.md "K with loaded faces"), integrated by crack_face_rule with `face_order` points
  /// per direction; both zero: no term, the results of an unloaded cut unchanged bit for bit.
  double face_pressure = 0.0;                                 ///< Pa, > 0 pushes the faces apart
  Eigen::Vector3d face_traction = Eigen::Vector3d::Zero();    ///< Pa, on the face above
  /// The contact pressure xfem-solve computed on the evaluated cut (xfem-front --contact-pressure),
  /// or null: a face load like face_pressure (it pushes the faces apart), p(x) interpolated at each
  /// face point with the weighted gap's shares (face_contact_pressure_at), added to face_pressure
  /// in the same crack-face term. Null or zero everywhere: no term from it.
  const FaceContactPressure* contact_pressure = nullptr;
  int face_order = 6;                                         ///< Gauss points per direction of the face rule
};

/// One evaluation point on the front.
struct FrontSif {
  int chain = 0;         ///< which front_polylines() chain
  double s = 0.0;        ///< arc length along the chain, metres
  Eigen::Vector3d x, a, b, c;  ///< position and frame
  double K1 = 0.0, K2 = 0.0, K3 = 0.0;  ///< Pa sqrt(m)
  double G = 0.0;        ///< energy release rate from the K's, J/m^2
  double q_trace = 0.0;  ///< Q, metres
  double curvature = 0.0;  ///< kappa of the front at the point, 1/m (c' = -kappa a: > 0 where the front bulges ahead)
  int tets = 0;          ///< tets integrated (those where q varies)
  bool end = false;      ///< an end of an open chain (on the body's surface): plane strain does not hold there
  /// The domain reaches the body's surface away from the front's ends: the domain form then
  /// misses a surface term and K is wrong unless that surface is traction free and parallel to a
  /// (reduce the radius).
  bool reaches_surface = false;
};

/// Several cuts: makes cut k's front, classes and surface em's own (em.front, em.cut_class, em.cut:
/// those front_stress_intensity evaluates). One cut: k must be 0. Throws xfem::Error naming `input`
/// for a cut the mesh does not have.
void select_front_of(EnrichedMesh& em, int k, const std::string& input);

/// The default domain radius: 2.5 x the mean edge length of the partially cut tets (those the
/// front crosses). Throws xfem::Error when there are none.
double default_domain_radius(const EnrichedMesh& em);

/// K_I, K_II, K_III and G at points spaced `spacing` apart along every chain of em's front
/// (both ends of an open chain included), for the solution u (3N scalars) of a body with Young's
/// modulus E, Poisson's ratio nu and body force `body` (N/m^3). `progress` (may be empty) gets
/// fractions 0..1. Throws xfem::Error for a wrong-sized u, an empty front, a bad option.
std::vector<FrontSif> front_stress_intensity(const EnrichedMesh& em, const Eigen::VectorXd& u, double E, double nu,
                                             const Eigen::Vector3d& body, const FrontSifOptions& options,
                                             const std::function<void(double)>& progress = {});

/// The same for a displacement gradient given as a function (row i, column j: du_i/dx_j at a
/// point x of tet t on `side` of the cut): an exact field fed in directly (tests), or the X-FEM
/// solution (the overload above passes displacement_gradient_at).
using DisplacementGradient = std::function<Eigen::Matrix3d(int t, const Eigen::Vector3d& x, int side)>;
std::vector<FrontSif> front_stress_intensity(const EnrichedMesh& em, const DisplacementGradient& grad_u, double E,
                                             double nu, const Eigen::Vector3d& body, const FrontSifOptions& options,
                                             const std::function<void(double)>& progress = {});

/// Every value the outputs hold (position, arc length, K_I, K_II, K_III, G) finite, else xfem::Error
/// "<solution>: G = inf at front point s = ... of chain ...: ..." (a solution of 1e200 m gives
/// finite K whose squares overflow G).
void check_front_finite(const std::vector<FrontSif>& points, const std::string& solution);

/// Writes the points as a VTK XML polydata (one polyline per chain, point arrays K_I, K_II, K_III
/// and G, SI units; docs/FORMATS.md "front.vtp") and as CSV (docs/FORMATS.md "front.csv").
void write_front_vtp(const std::vector<FrontSif>& points, const std::string& path);
void write_front_csv(const std::vector<FrontSif>& points, const std::string& path);

}  // namespace xfem
