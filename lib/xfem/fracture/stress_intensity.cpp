// SPDX-License-Identifier: MIT
#include "xfem/fracture/stress_intensity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <unordered_map>

#include "xfem/core/atomic_file.h"
#include "xfem/enrich/branch_functions.h"
#include "xfem/integrate/conforming_quadrature.h"
#include "xfem/integrate/element_stiffness.h"
#include "xfem/enrich/enriched_basis.h"
#include "xfem/enrich/side_codes.h"
#include "xfem/core/error.h"
#include "xfem/core/regions.h"
#include "xfem/fracture/crack_face_rule.h"
#include "xfem/fracture/exact_fields.h"
#include "xfem/fracture/front_cost.h"
#include "xfem/geometry/point_location.h"
#include "xfem/geometry/tet_shape.h"

namespace xfem {

void select_front_of(EnrichedMesh& em, int k, const std::string& input) {
  if (em.cuts.empty()) {
    if (k != 0) throw Error(input + ": --front-of " + std::to_string(k) + " but the mesh has one cut");
    return;
  }
  if (k < 0 || k >= static_cast<int>(em.cuts.size()))
    throw Error(input + ": --front-of " + std::to_string(k) + " but the mesh has " + std::to_string(em.cuts.size()) +
                " cuts (0.." + std::to_string(em.cuts.size() - 1) + ")");
  em.front = em.cuts[k].front;
  em.cut_class = em.cuts[k].cut_class;
  em.cut = em.cuts[k].cut;
}

double default_domain_radius(const EnrichedMesh& em) {
  double sum = 0.0;
  long edges = 0;
  for (int t = 0; t < em.tets(); ++t) {
    if (em.cut_class.empty() || em.cut_class[t] != 1) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        sum += (em.mesh.points.row(em.mesh.tets(t, i)) - em.mesh.points.row(em.mesh.tets(t, j))).norm();
        ++edges;
      }
  }
  if (edges == 0) throw Error("no partially cut tets: the cut has no front inside the body");
  return 2.5 * sum / static_cast<double>(edges);
}

namespace {

// Levels of 4-fold splitting of a surface triangle near the front's end (1/r integrand) and across
// the cut (a jump): with the exact Williams fields the end points' K converge to 5e-5 with these.
constexpr int kSurfaceLevelsFront = 12, kSurfaceLevelsCut = 8;

Eigen::Matrix3d stress(const Eigen::Matrix3d& grad, const Lame& m) {
  const Eigen::Matrix3d eps = 0.5 * (grad + grad.transpose());
  return m.lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2.0 * m.mu * eps;
}

// A face of the body's surface: its tet, its nodes, its outward unit normal.
struct SurfaceFace {
  int tet = 0;
  std::array<int, 3> nodes{};
  Eigen::Vector3d normal;
};

// Radon's 7-point rule on a triangle (degree 5): barycentric coordinates and weights (sum 1).
const std::array<std::array<double, 4>, 7>& triangle_rule() {
  static const std::array<std::array<double, 4>, 7> r = [] {
    const double s = std::sqrt(15.0);
    const double a1 = (6 - s) / 21, b1 = (9 + 2 * s) / 21, w1 = (155 - s) / 1200;
    const double a2 = (6 + s) / 21, b2 = (9 - 2 * s) / 21, w2 = (155 + s) / 1200;
    return std::array<std::array<double, 4>, 7>{{{1.0 / 3, 1.0 / 3, 1.0 / 3, 9.0 / 40},
                                                 {a1, a1, b1, w1}, {a1, b1, a1, w1}, {b1, a1, a1, w1},
                                                 {a2, a2, b2, w2}, {a2, b2, a2, w2}, {b2, a2, a2, w2}}};
  }();
  return r;
}

// With several cuts: the index of em.cut, the cut whose front is evaluated, in em.cuts; -1 for one cut.
int evaluated_cut(const EnrichedMesh& em) {
  if (em.cuts.empty()) return -1;
  for (std::size_t k = 0; k < em.cuts.size(); ++k)
    if (em.cuts[k].cut == em.cut) return static_cast<int>(k);
  throw Error("the evaluated cut is not one of the mesh's cuts (select it with select_front_of)");
}

// The side code (side_codes.h) of a point x off the integration rule (a surface point of the domain
// form): its side of every cut, `side` for the evaluated cut (that of the auxiliary fields), a point
// on another cut's surface taken on its + side.
int side_code_at(const EnrichedMesh& em, int evaluated, int side, const Eigen::Vector3d& x) {
  int sides[kMaxCuts];
  for (std::size_t k = 0; k < em.cuts.size(); ++k)
    sides[k] = static_cast<int>(k) == evaluated ? side : em.cuts[k].cut->side(x) < 0 ? -1 : 1;
  return pack_sides(sides, static_cast<int>(em.cuts.size()));
}

// The integration points of one tet and the solution's gradient at each, computed once: the
// domains of neighbouring front points overlap.
struct TetPoints {
  PointRule rule;
  std::vector<Eigen::Matrix3d> grad_u, sigma;
};

// The material of the interaction integral's domain at front point f (the tets where the weight q
// is positive at a node). The domain form without an interface term holds for one material only:
// a domain holding two is refused, naming their regions.
int domain_material(const EnrichedMesh& em, const TetMaterials& materials, const std::vector<double>& q,
                    const FrontSif& f, double R) {
  const TetMesh& mesh = em.mesh;
  int material = -1;
  long first = -1;
  for (int t = 0; t < em.tets(); ++t) {
    if (q[mesh.tets(t, 0)] <= 0 && q[mesh.tets(t, 1)] <= 0 && q[mesh.tets(t, 2)] <= 0 && q[mesh.tets(t, 3)] <= 0)
      continue;
    const int m = materials.index(t);
    if (material < 0) {
      material = m;
      first = t;
    } else if (m != material) {
      const std::vector<int> region = tet_regions(mesh);
      throw Error("front point at s = " + short_number(f.s) + " m of chain " + std::to_string(f.chain) +
                  ": the interaction integral's domain (radius " + short_number(R) +
                  " m) holds tets of two materials (regions " + std::to_string(region[static_cast<std::size_t>(first)]) +
                  " and " + std::to_string(region[static_cast<std::size_t>(t)]) +
                  "), and the domain form without an interface term needs one: reduce --radius");
    }
  }
  return material < 0 ? 0 : material;
}

}  // namespace

std::vector<FrontSif> front_stress_intensity(const EnrichedMesh& em, const Eigen::VectorXd& u, double E, double nu,
                                             const Eigen::Vector3d& body, const FrontSifOptions& options,
                                             const std::function<void(double)>& progress) {
  if (u.size() != 3 * em.n)
    throw Error("solution: " + std::to_string(u.size()) + " values, expected 3N = " + std::to_string(3 * em.n));
  return front_stress_intensity(
      em, [&](int t, const Eigen::Vector3d& x, int side) { return displacement_gradient_at(em, t, x, side, u); }, E, nu,
      body, options, progress);
}

std::vector<FrontSif> front_stress_intensity(const EnrichedMesh& em, const DisplacementGradient& grad_u, double E,
                                             double nu, const Eigen::Vector3d& body, const FrontSifOptions& options,
                                             const std::function<void(double)>& progress) {
  if (em.front.empty()) throw Error("the cut has no front inside the body: no stress intensity factors to compute");
  if (!(options.plateau >= 0.0 && options.plateau < 1.0)) throw Error("plateau must lie in [0, 1)");
  if (options.order < 1 || options.order > 20) throw Error("order must lie in 1..20");
  const double R = options.radius > 0 ? options.radius : default_domain_radius(em);
  if (!std::isfinite(R) || !(R > 0)) throw Error("domain radius must be positive");
  const std::vector<FrontPolyline> chains = front_polylines(em.front);
  const Lame lm = lame(E, nu);
  const TetMesh& mesh = em.mesh;
  // Several materials (problem.json `materials`): each point's domain must hold one, whose E and
  // nu then replace the arguments' (checked per front point below).
  const bool multi = options.materials && !options.materials->of_tet.empty();
  if (multi && options.materials->of_tet.size() != static_cast<std::size_t>(em.tets()))
    throw Error("front_stress_intensity: " + std::to_string(options.materials->of_tet.size()) + " materials for " +
                std::to_string(em.tets()) + " tets");
  const long np = mesh.points.rows();
  const CutElementSplits splits = split_cut_elements(em);
  const int evaluated = evaluated_cut(em);
  const PointLocator locator(mesh);
  std::unordered_map<int, TetPoints> cache;
  const auto points_of = [&](int t) -> const TetPoints& {
    auto it = cache.find(t);
    if (it != cache.end()) return it->second;
    TetPoints tp;
    conforming_rule(em, splits, t, options.order, tp.rule);
    for (int k = 0; k < tp.rule.size(); ++k) {
      int side = tp.rule.side[k];
      if (side == 0 && em.cut && em.cuts.empty()) side = em.cut->side(tp.rule.x[k]);  // several cuts: 0 = decide by all
      tp.grad_u.push_back(grad_u(t, tp.rule.x[k], side));
      // Several cuts: that side is a side code (side_codes.h); the auxiliary fields want the
      // point's side of the evaluated cut, the one the code holds (or, for code 0, its surface's).
      tp.rule.side[k] = evaluated < 0 ? side : side >= 2 ? code_side(side, evaluated) : em.cut->side(tp.rule.x[k]);
      tp.sigma.push_back(stress(tp.grad_u.back(), multi ? options.materials->lame(t) : lm));
    }
    return cache.emplace(t, std::move(tp)).first->second;
  };

  // Each node's closest point on each chain.
  std::vector<std::vector<double>> node_s(chains.size()), node_rho(chains.size());
  for (std::size_t p = 0; p < chains.size(); ++p) {
    node_s[p].resize(np);
    node_rho[p].resize(np);
    for (long k = 0; k < np; ++k) chains[p].closest(mesh.points.row(k).transpose(), node_s[p][k], node_rho[p][k]);
  }

  // The cost guard (front_cost.h), before any of the work it estimates.
  const FrontCost cost = front_cost(em, chains, node_rho, R, options.spacing, options.order);
  check_front_cost(cost, options.allow_large);

  // Front points: evenly spaced along each chain, both ends of an open chain included.
  std::vector<FrontSif> out;
  std::vector<double> halfwidth;
  for (std::size_t p = 0; p < chains.size(); ++p) {
    const FrontPolyline& ch = chains[p];
    const double want = options.spacing > 0 ? options.spacing : R;
    const int n = std::max(1, static_cast<int>(std::lround(ch.length / want)));
    const double d = ch.length / n;
    for (int i = 0; i <= n; ++i) {
      if (ch.closed && i == n) break;
      FrontSif f;
      f.chain = static_cast<int>(p);
      f.s = i * d;
      f.x = ch.position(f.s);
      ch.frame(f.s, f.c, f.b);
      f.a = f.b.cross(f.c);
      f.end = !ch.closed && (i == 0 || i == n);
      out.push_back(f);
      halfwidth.push_back(d);
    }
  }

  // Nodes on the body's surface (on a face of one tet only): a domain reaching them away from the
  // front's ends misses the surface term of the domain form.
  std::vector<char> on_surface(np, 0);
  std::vector<SurfaceFace> surface;
  {
    std::map<std::array<int, 3>, std::pair<int, int>> faces;  // sorted nodes -> (uses, tet)
    for (int t = 0; t < em.tets(); ++t)
      for (int k = 0; k < 4; ++k) {
        std::array<int, 3> f;
        for (int i = 0, j = 0; i < 4; ++i)
          if (i != k) f[j++] = mesh.tets(t, i);
        std::sort(f.begin(), f.end());
        auto& e = faces[f];
        ++e.first;
        e.second = t;
      }
    for (const auto& [f, e] : faces)
      if (e.first == 1) {
        for (int n : f) on_surface[n] = 1;
        SurfaceFace sf;
        sf.tet = e.second;
        sf.nodes = f;
        const Eigen::Vector3d p0 = mesh.points.row(f[0]), p1 = mesh.points.row(f[1]), p2 = mesh.points.row(f[2]);
        sf.normal = (p1 - p0).cross(p2 - p0).normalized();
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int i = 0; i < 4; ++i) centroid += 0.25 * mesh.points.row(mesh.tets(sf.tet, i)).transpose();
        if (sf.normal.dot(centroid - p0) > 0) sf.normal = -sf.normal;  // outward
        surface.push_back(sf);
      }
  }

  // The longest edge of the mesh: how far the interpolated q reaches beyond the nodes where it is set.
  double h_max = 0.0;
  for (int t = 0; t < em.tets(); ++t)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        h_max = std::max(h_max, (mesh.points.row(mesh.tets(t, i)) - mesh.points.row(mesh.tets(t, j))).norm());

  // Loaded faces: the crack-face term's points, once (stress_intensity.h), in the tets with a node
  // within R of the front (elsewhere q = 0 for every front point).
  bool pressed = false;  // a contact pressure somewhere on the faces
  if (options.contact_pressure)
    for (double p : options.contact_pressure->pressure) pressed = pressed || p != 0.0;
  const bool loaded = options.face_pressure != 0.0 || options.face_traction.norm() > 0.0 || pressed;
  if (loaded && options.face_order < 1) throw Error("face_order must be at least 1");
  std::vector<CrackFacePoint> face_points;
  if (loaded) {
    std::vector<char> near(static_cast<std::size_t>(em.tets()), 0);
    for (int t = 0; t < em.tets(); ++t)
      for (int c = 0; c < 4 && !near[static_cast<std::size_t>(t)]; ++c)
        for (std::size_t p = 0; p < chains.size(); ++p)
          if (node_rho[p][mesh.tets(t, c)] < R) near[static_cast<std::size_t>(t)] = 1;
    face_points = crack_face_rule(em, options.face_order, near);
  }

  const double denom12 = E / (2.0 * (1.0 - nu * nu));
  const bool has_body = body.norm() > 0;
  std::vector<double> q(np);
  for (std::size_t k = 0; k < out.size(); ++k) {
    FrontSif& f = out[k];
    const FrontPolyline& ch = chains[f.chain];
    const double d = halfwidth[k];
    for (long n = 0; n < np; ++n) {
      const double rho = node_rho[f.chain][n];
      const double qr = rho <= options.plateau * R ? 1.0 : std::max(0.0, (R - rho) / ((1.0 - options.plateau) * R));
      const double qt = std::max(0.0, 1.0 - std::abs(ch.arc_offset(f.s, node_s[f.chain][n])) / d);
      q[n] = qr * qt;
      const double sn = node_s[f.chain][n];
      if (q[n] > 0 && on_surface[n] && (ch.closed || (sn > 1e-9 * ch.length && sn < (1 - 1e-9) * ch.length))) f.reaches_surface = true;
    }
    const int material = multi ? domain_material(em, *options.materials, q, f, R) : 0;
    const double E_f = multi ? options.materials->E[material] : E, nu_f = multi ? options.materials->nu[material] : nu;
    const Lame lm_f = multi ? options.materials->laws[material].lame : lm;
    const double denom_f = multi ? E_f / (2.0 * (1.0 - nu_f * nu_f)) : denom12;
    // Q: the trace of the interpolated q along the chain, by 2-point Gauss on 64 pieces per half-width.
    // The interpolated q reaches beyond s +- d by up to an element (a node inside the hat carries q
    // over its whole star): the trace is integrated over s +- (d + 2 h_max). (Cut at s +- d, Q
    // missed those tails and K came out too large by up to several % where the hat's ends fall
    // between nodes.)
    double Q = 0.0;
    const double reach = d + 2.0 * h_max;
    const bool whole = ch.closed && 2.0 * reach >= ch.length;
    const double lo = whole ? 0.0 : ch.closed ? f.s - reach : std::max(0.0, f.s - reach);
    const double hi = whole ? ch.length : ch.closed ? f.s + reach : std::min(ch.length, f.s + reach);
    const int pieces = std::max(128, static_cast<int>(std::ceil(64.0 * (hi - lo) / d)));
    const double h = (hi - lo) / pieces;
    for (int i = 0; i < pieces; ++i)
      for (const double g : {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}) {
        const Eigen::Vector3d x = ch.position(lo + h * (i + 0.5 + 0.5 * g));
        const int t = locator.nearest(x, R);
        if (t < 0) continue;
        const Eigen::Vector4d l = locator.barycentric(t, x);
        double qx = 0.0;
        for (int c = 0; c < 4; ++c) qx += l[c] * q[mesh.tets(t, c)];
        Q += 0.5 * h * qx;
      }
    if (!(Q > 0))
      throw Error("front point at s = " + std::to_string(f.s) + ": the domain weight q vanishes on the front (the "
                  "spacing or the radius is smaller than the elements there: increase them)");
    f.q_trace = Q;

    // The front's curvature at P: the turn of the tangent over the hat, kappa = asin(-(c+ - c-).a / 2) / d
    // (exact on a circle), c' = -kappa a. The osculating circle in the cut's plane at P carries the
    // auxiliary fields (stress_intensity.h).
    const bool tangent = options.auxiliary == FrontAuxiliary::Tangent;
    const bool corrected = options.auxiliary == FrontAuxiliary::Curvilinear;
    double kappa = 0.0;
    if (!tangent) {
      const double s0 = ch.closed ? f.s - d : std::max(0.0, f.s - d), s1 = ch.closed ? f.s + d : std::min(ch.length, f.s + d);
      Eigen::Vector3d c0, b0, c1, b1;
      ch.frame(s0, c0, b0);
      ch.frame(s1, c1, b1);
      const double half = 0.5 * (s1 - s0);
      if (half > 0) kappa = std::asin(std::clamp(-0.5 * (c1 - c0).dot(f.a), -1.0, 1.0)) / half;
      if (std::abs(kappa) * R < 1e-9) kappa = 0.0;
      if (std::abs(kappa) * R >= 0.9)
        throw Error("front point at s = " + std::to_string(f.s) + ": the front's radius of curvature (" +
                    std::to_string(1 / std::abs(kappa)) + " m) is not larger than the domain radius " +
                    std::to_string(R) + " m: reduce --radius");
    }
    f.curvature = kappa;

    // The auxiliary fields: the crack-tip functions' coefficients of unit K_I, K_II, K_III in a
    // frame (a, b, c) = the columns of the identity (rotated into each point's frame below), or in
    // P's frame for the tangent-line fields.
    WilliamsField aux;
    aux.origin = tangent ? f.x : Eigen::Vector3d::Zero();
    aux.a = tangent ? f.a : Eigen::Vector3d::UnitX();
    aux.b = tangent ? f.b : Eigen::Vector3d::UnitY();
    aux.E = E_f;
    aux.nu = nu_f;
    std::array<Eigen::Matrix<double, 3, 4>, 3> C;
    for (int m = 0; m < 3; ++m) {
      aux.K1 = m == 0;
      aux.K2 = m == 1;
      aux.K3 = m == 2;
      C[m] = aux.branch_coefficients();
    }
    const CrackTipFrame frame_P = aux.frame();
    const Eigen::Vector3d centre = kappa != 0 ? Eigen::Vector3d(f.x - f.a / kappa) : f.x;
    const Eigen::Vector3d nrm = f.b;
    // The auxiliary fields' frame at x (ax, nrm, cx), kappa / h there and the crack-tip functions;
    // false on the osculating circle's axis (kappa R < 0.9 keeps every domain away from it).
    // `face_xa` (a face point of the crack-face term): the point's xa, its distance behind the cut's
    // own front (NaN: the toroidal coordinate).
    const auto aux_at = [&](const Eigen::Vector3d& x, int side, Eigen::Vector3d& ax, Eigen::Vector3d& cx, double& kh,
                            BranchValues& F, double face_xa = std::numeric_limits<double>::quiet_NaN()) {
      ax = f.a;
      cx = f.c;
      kh = 0.0;
      if (tangent) {
        F = branch_functions(frame_P, x, side);
        return true;
      }
      TipCoordinates tc;
      if (kappa != 0.0) {
        const Eigen::Vector3d v = x - centre;
        const Eigen::Vector3d vp = v - v.dot(nrm) * nrm;
        const double rho = vp.norm();
        if (!(rho > 0)) return false;
        ax = (kappa > 0 ? 1.0 : -1.0) * vp / rho;
        cx = ax.cross(nrm);
        tc.xa = (kappa > 0 ? 1.0 : -1.0) * (rho - 1.0 / std::abs(kappa));
        kh = kappa / (1.0 + kappa * tc.xa);
      } else {
        tc.xa = ax.dot(x - f.x);
      }
      tc.xb = nrm.dot(x - f.x);
      if (!std::isnan(face_xa)) tc.xa = face_xa, tc.xb = 0.0;
      tc.grad.row(0) = ax.transpose();
      tc.grad.row(1) = nrm.transpose();
      F = branch_functions(tc, side);
      return true;
    };
    Eigen::Vector3d I = Eigen::Vector3d::Zero();
    for (int t = 0; t < em.tets(); ++t) {
      double qmin = 1.0, qmax = 0.0;
      for (int c = 0; c < 4; ++c) {
        qmin = std::min(qmin, q[mesh.tets(t, c)]);
        qmax = std::max(qmax, q[mesh.tets(t, c)]);
      }
      // Where q is constant only the terms weighted by q itself contribute: the body force's and the
      // curvature's.
      if (qmax == 0.0 || (qmax == qmin && !has_body && kappa == 0.0)) continue;
      ++f.tets;
      const TetShape shape = tet_shape(mesh, t);
      Eigen::Vector4d qc;
      for (int c = 0; c < 4; ++c) qc[c] = q[mesh.tets(t, c)];
      const Eigen::Vector3d gq = shape.grad.transpose() * qc;
      const TetPoints& tp = points_of(t);
      for (int i = 0; i < tp.rule.size(); ++i) {
        const Eigen::Vector3d& x = tp.rule.x[i];
        Eigen::Vector3d ax, cx;
        BranchValues F;
        double kh = 0.0;
        if (!aux_at(x, tp.rule.side[i], ax, cx, kh, F)) continue;
        Eigen::Matrix3d Rx;
        Rx << ax, nrm, cx;
        const Eigen::Matrix3d& Gu = tp.grad_u[i];
        const Eigen::Matrix3d& S = tp.sigma[i];
        const Eigen::Vector3d Gu_a = Gu * ax, S_gq = S * gq;
        const double qx = shape.values(x).dot(qc);
        for (int m = 0; m < 3; ++m) {
          const Eigen::Matrix3d Ga = tangent ? Eigen::Matrix3d(C[m] * F.dF) : Eigen::Matrix3d(Rx * C[m] * F.dF);
          const Eigen::Matrix3d Sa = stress(Ga, lm_f);
          const Eigen::Matrix3d ea = 0.5 * (Ga + Ga.transpose());
          const double Se = S.cwiseProduct(ea).sum();
          const Eigen::Vector3d Ga_a = Ga * ax;
          double integrand = Ga_a.dot(S_gq) + Gu_a.dot(Sa * gq) - Se * ax.dot(gq) - qx * body.dot(Ga_a);
          if (kh != 0.0) {
            // grad a = kappa / h c c^T: -q kappa / h P_cc, P_cc = sigma:eps^aux - (sigma^aux c).(grad u c).
            double extra = -(Se - (Sa * cx).dot(Gu * cx));
            if (corrected) {
              // Incompatibility, sigma_ij (eps^aux_ij,k - H_ik,j) a_k, and non-equilibrium, -div(sigma^aux).(grad u a).
              extra += ax.dot(Ga_a) * cx.dot(S * cx) - cx.dot(Ga_a) * ax.dot(S * cx);
              const Eigen::Vector3d Sa_a = Sa * ax, Sa_c = Sa * cx;
              extra += (ax.dot(Sa_a) - cx.dot(Sa_c)) * ax.dot(Gu_a) + nrm.dot(Sa_a) * nrm.dot(Gu_a) +
                       2.0 * ax.dot(Sa_c) * cx.dot(Gu_a);
            }
            integrand += qx * kh * extra;
          }
          I[m] += tp.rule.weights[i] * integrand;
        }
      }
    }
    // Loaded faces: - int over the cut of q (p n + t) . [[H a]] dA (stress_intensity.h), the jump
    // of the auxiliary gradient's a-column between the face above and the face below, ~ rho^-1/2.
    // rho is measured to the cut's own front (the chain), not to the osculating circle: the
    // circle through P strays from the polygonal front by up to its sagitta delta, and the
    // faces between them would carry sqrt(delta / R) of the term (2.5 % on the pipeline's
    // 96-gon at R = 0.1); measured to the front, what is left is O(delta / R).
    for (const CrackFacePoint& fp : face_points) {
      Eigen::Vector4d qc;
      for (int c = 0; c < 4; ++c) qc[c] = q[mesh.tets(fp.tet, c)];
      if (qc.maxCoeff() == 0.0) continue;
      const double qx = tet_shape(mesh, fp.tet).values(fp.x).dot(qc);
      if (qx == 0.0) continue;
      Eigen::Vector3d ax[2], cx;
      BranchValues F[2];
      double kh;
      double s_foot, rho;
      ch.closest(fp.x, s_foot, rho);
      const double face_xa = tangent ? std::numeric_limits<double>::quiet_NaN() : -rho;
      if (!aux_at(fp.x, 1, ax[0], cx, kh, F[0], face_xa) || !aux_at(fp.x, -1, ax[1], cx, kh, F[1], face_xa)) continue;
      Eigen::Matrix3d Rx;
      Rx << ax[0], nrm, cx;
      const double contact = pressed ? face_contact_pressure_at(*options.contact_pressure, mesh, fp.tet, fp.x) : 0.0;
      const Eigen::Vector3d load = (options.face_pressure + contact) * fp.normal + options.face_traction;
      for (int m = 0; m < 3; ++m) {
        const Eigen::Vector3d jump = tangent ? Eigen::Vector3d(C[m] * (F[0].dF - F[1].dF) * ax[0])
                                             : Eigen::Vector3d(Rx * C[m] * (F[0].dF - F[1].dF) * ax[0]);
        I[m] -= fp.weight * qx * load.dot(jump);
      }
    }
    // At an end of an open chain the domain meets the body's surface where the front does: the
    // surface term of the domain form, int q [sigma:eps^aux (a.n) - (sigma n).(H a) - (sigma^aux n).(grad u a)] dS,
    // over the surface faces where q > 0 (on a traction-free face only the last part is left: the
    // plane-strain auxiliary field is not traction-free there). The integrand is singular like 1/r
    // at the front's end and jumps across the cut: triangles near either are split 4-fold, up to
    // kSurfaceLevelsFront / kSurfaceLevelsCut times, Radon's rule on each piece.
    if (f.end && options.surface_term) {
      const auto& rule = triangle_rule();
      std::function<void(const SurfaceFace&, const Eigen::Vector3d&, const Eigen::Vector3d&, const Eigen::Vector3d&,
                         const Eigen::Vector3d&, int)>
          integrate;
      integrate = [&](const SurfaceFace& sf, const Eigen::Vector3d& A, const Eigen::Vector3d& B,
                      const Eigen::Vector3d& Cc, const Eigen::Vector3d& qabc, int level) {
        const double size = std::max({(B - A).norm(), (Cc - B).norm(), (A - Cc).norm()});
        const Eigen::Vector3d mid = (A + B + Cc) / 3.0;
        double sd, dist;
        ch.closest(mid, sd, dist);
        bool split = dist < 1.5 * size && level < kSurfaceLevelsFront;
        if (!split && em.cut && level < kSurfaceLevelsCut) {
          int plus = 0, minus = 0;
          for (const Eigen::Vector3d* v : {&A, &B, &Cc, &mid}) {
            const int sv = em.cut->side(*v);
            plus += sv > 0;
            minus += sv < 0;
          }
          split = plus > 0 && minus > 0;
        }
        if (split) {
          const Eigen::Vector3d ab = 0.5 * (A + B), bc = 0.5 * (B + Cc), ca = 0.5 * (Cc + A);
          const Eigen::Vector3d qab(0.5 * (qabc[0] + qabc[1]), 0.5 * (qabc[1] + qabc[2]), 0.5 * (qabc[2] + qabc[0]));
          integrate(sf, A, ab, ca, Eigen::Vector3d(qabc[0], qab[0], qab[2]), level + 1);
          integrate(sf, ab, B, bc, Eigen::Vector3d(qab[0], qabc[1], qab[1]), level + 1);
          integrate(sf, ca, bc, Cc, Eigen::Vector3d(qab[2], qab[1], qabc[2]), level + 1);
          integrate(sf, ab, bc, ca, Eigen::Vector3d(qab[0], qab[1], qab[2]), level + 1);
          return;
        }
        const double area = 0.5 * (B - A).cross(Cc - A).norm();
        for (const auto& r : rule) {
          const Eigen::Vector3d x = r[0] * A + r[1] * B + r[2] * Cc;
          const double qx = r[0] * qabc[0] + r[1] * qabc[1] + r[2] * qabc[2];
          if (qx == 0.0) continue;
          int side = em.cut ? em.cut->side(x) : 1;
          if (side == 0) side = 1;
          Eigen::Vector3d ax, cx;
          BranchValues F;
          double kh;
          if (!aux_at(x, side, ax, cx, kh, F)) continue;
          Eigen::Matrix3d Rx;
          Rx << ax, nrm, cx;
          const Eigen::Matrix3d Gu = grad_u(sf.tet, x, evaluated < 0 ? side : side_code_at(em, evaluated, side, x));
          const Eigen::Matrix3d S = stress(Gu, lm_f);
          const Eigen::Vector3d Sn = S * sf.normal, Gu_a = Gu * ax;
          for (int m = 0; m < 3; ++m) {
            const Eigen::Matrix3d Ga = tangent ? Eigen::Matrix3d(C[m] * F.dF) : Eigen::Matrix3d(Rx * C[m] * F.dF);
            const Eigen::Matrix3d Sa = stress(Ga, lm_f);
            const double Se = S.cwiseProduct(0.5 * (Ga + Ga.transpose())).sum();
            I[m] += r[3] * area * qx * (Se * ax.dot(sf.normal) - Sn.dot(Ga * ax) - (Sa * sf.normal).dot(Gu_a));
          }
        }
      };
      for (const SurfaceFace& sf : surface) {
        const Eigen::Vector3d qn(q[sf.nodes[0]], q[sf.nodes[1]], q[sf.nodes[2]]);
        if (qn.maxCoeff() == 0.0) continue;
        integrate(sf, mesh.points.row(sf.nodes[0]).transpose(), mesh.points.row(sf.nodes[1]).transpose(),
                  mesh.points.row(sf.nodes[2]).transpose(), qn, 0);
      }
    }
    I /= Q;
    f.K1 = denom_f * I[0];
    f.K2 = denom_f * I[1];
    f.K3 = lm_f.mu * I[2];
    f.G = (f.K1 * f.K1 + f.K2 * f.K2) / (2.0 * denom_f) + f.K3 * f.K3 / (2.0 * lm_f.mu);
    if (progress) progress(static_cast<double>(k + 1) / static_cast<double>(out.size()));
  }
  return out;
}

namespace {

void write_text(const std::string& path, const std::function<void(std::ostream&)>& body) {
  write_atomically(path, [&](const std::string& tmp) {
    std::ofstream os(tmp, std::ios::binary);
    if (!os) throw Error(path + ": cannot open for writing");
    os << std::setprecision(10);
    body(os);
    os.flush();
    if (!os) throw Error(path + ": write failed");
  });
}

}  // namespace

void check_front_finite(const std::vector<FrontSif>& points, const std::string& solution) {
  for (const FrontSif& p : points) {
    const std::pair<const char*, double> values[] = {{"K_I", p.K1}, {"K_II", p.K2}, {"K_III", p.K3}, {"G", p.G},
                                                     {"the arc length", p.s}, {"x", p.x[0]}, {"y", p.x[1]},
                                                     {"z", p.x[2]}};
    for (const auto& [name, v] : values)
      if (!std::isfinite(v)) {
        char value[32];
        std::snprintf(value, sizeof value, "%g", v);
        throw Error(solution + ": " + name + " = " + value + " at the front point at arc length " +
                    std::to_string(p.s) + " of chain " + std::to_string(p.chain) +
                    ": not a finite number (are the solution's values, or E, far too large?)");
      }
  }
}

void write_front_vtp(const std::vector<FrontSif>& points, const std::string& path) {
  write_text(path, [&](std::ostream& os) {
    // One polyline per chain; a closed chain repeats its first point's index.
    std::vector<long> conn, offsets;
    for (std::size_t i = 0; i < points.size(); ++i) {
      conn.push_back(static_cast<long>(i));
      const bool last = i + 1 == points.size() || points[i + 1].chain != points[i].chain;
      if (last) {
        std::size_t first = i;
        while (first > 0 && points[first - 1].chain == points[i].chain) --first;
        if (!points[first].end && i > first) conn.push_back(static_cast<long>(first));
        offsets.push_back(static_cast<long>(conn.size()));
      }
    }
    os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
       << "<PolyData>\n<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfVerts=\"0\" NumberOfLines=\""
       << offsets.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<PointData Scalars=\"K_I\">\n";
    const auto scalar = [&](const char* name, const std::function<double(const FrontSif&)>& get) {
      os << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
      for (const auto& p : points) os << get(p) << "\n";
      os << "</DataArray>\n";
    };
    scalar("K_I", [](const FrontSif& p) { return p.K1; });
    scalar("K_II", [](const FrontSif& p) { return p.K2; });
    scalar("K_III", [](const FrontSif& p) { return p.K3; });
    scalar("G", [](const FrontSif& p) { return p.G; });
    scalar("arc_length", [](const FrontSif& p) { return p.s; });
    const auto vector = [&](const char* name, const std::function<Eigen::Vector3d(const FrontSif&)>& get) {
      os << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto& p : points) {
        const Eigen::Vector3d v = get(p);
        os << v[0] << " " << v[1] << " " << v[2] << "\n";
      }
      os << "</DataArray>\n";
    };
    vector("ahead", [](const FrontSif& p) { return p.a; });
    vector("normal", [](const FrontSif& p) { return p.b; });
    vector("tangent", [](const FrontSif& p) { return p.c; });
    os << "</PointData>\n<Points>\n";
    os << "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : points) os << p.x[0] << " " << p.x[1] << " " << p.x[2] << "\n";
    os << "</DataArray>\n</Points>\n<Lines>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (long c : conn) os << c << "\n";
    os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (long o : offsets) os << o << "\n";
    os << "</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  });
}

void write_front_csv(const std::vector<FrontSif>& points, const std::string& path) {
  write_text(path, [&](std::ostream& os) {
    os << "chain,arc_length,x,y,z,K_I,K_II,K_III,G,end\n";
    for (const auto& p : points)
      os << p.chain << "," << p.s << "," << p.x[0] << "," << p.x[1] << "," << p.x[2] << "," << p.K1 << "," << p.K2
         << "," << p.K3 << "," << p.G << "," << (p.end ? 1 : 0) << "\n";
  });
}

}  // namespace xfem
