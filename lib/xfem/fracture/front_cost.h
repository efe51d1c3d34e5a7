// SPDX-License-Identifier: MIT
#pragma once
#include <vector>

#include "xfem/enrich/enriched_mesh.h"
#include "xfem/geometry/crack_front.h"

namespace xfem {

/// xfem-front's cost guard (the model of xfem-mesh's, generation_limits.h): what
/// front_stress_intensity is about to do, estimated before it does any of it. A tiny --spacing or
/// --radius asks for millions of front points (memory runs out), a high --order for hundreds of
/// millions of integration points (gigabytes, minutes).
struct FrontCost {
  /// Front points: per chain round(length / d) + 1 (d the spacing, R by default).
  double points = 0;
  /// Evaluations of the weight q along the front for its trace Q: per front point
  /// 2 max(128, 64 (2 d + 4 h) / d), h the longest edge.
  double trace_points = 0;
  /// The conforming rule's points in the tets with a node closer than R to the front, each kept
  /// (~200 bytes: the solution's gradient and stress) for the domains that share it. Per tet n^3
  /// (n = --order) times its sub-tets: a cut tet about 16 (L + 1), L = min(8, (n - 2)^2) the
  /// bisection levels next to the front (conforming_quadrature.h), any other 1 + min(8, 2 (n - 3)) / 2.
  /// Measured on the incisions pipeline (n = 2, 4, 6, 8): 0.5 to 0.9 times this.
  double integration_points = 0;
  /// Evaluations of the interaction integral's integrand: each integration point in the domains of
  /// about min(points, 2 (d + 2 h) / d) front points.
  double evaluations = 0;
};

/// Beyond these xfem-front refuses to start unless --allow-large (docs/FORMATS.md "front.csv").
/// Measured on the incisions pipeline (2 cores): 2.4e7 integration points (order 8) held 4.7 GB
/// and took 24 s with 1.9e8 integrand evaluations.
constexpr double kMaxFrontPoints = 1e5, kMaxFrontTracePoints = 1e8, kMaxFrontIntegrationPoints = 2e7,
                 kMaxFrontEvaluations = 4e8;

/// The estimate for em's front (its chains `chains`), domain radius R, point spacing (0: R) and
/// conforming order; node_rho[p][n]: node n's distance to chain p.
FrontCost front_cost(const EnrichedMesh& em, const std::vector<FrontPolyline>& chains,
                     const std::vector<std::vector<double>>& node_rho, double R, double spacing, int order);

/// Throws xfem::Error "about P front points, ... requested (limits ...; a larger --spacing or
/// --radius, a lower --order, or --allow-large)" when an estimate exceeds its limit (or is not a
/// number) and `allowed` is false.
void check_front_cost(const FrontCost& cost, bool allowed);

}  // namespace xfem
