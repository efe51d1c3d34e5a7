// SPDX-License-Identifier: MIT
#pragma once
#include <Eigen/Dense>
#include <string>

namespace xfem {

/// Williams near-tip displacement field of a straight cut front (modes I, II: plane strain with
/// kappa = 3 - 4 nu; mode III: anti-plane shear), an exact solution of 3D linear elasticity with
/// traction-free cut faces. Frame of DESIGN.md: the front is the line through `origin` along c;
/// b is the cut's unit normal; a = b x c points ahead into intact material; the cut is the
/// half-plane xb = 0, xa < 0, with theta = +-pi on its two faces.
struct WilliamsField {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d a = Eigen::Vector3d::UnitX();  ///< unit, ahead of the front
  Eigen::Vector3d b = Eigen::Vector3d::UnitY();  ///< unit, the cut's normal
  double K1 = 0.0, K2 = 0.0, K3 = 0.0;          ///< stress intensity factors, Pa sqrt(m)
  double E = 1.0, nu = 0.3;                      ///< Young's modulus (Pa), Poisson's ratio

  /// Displacement at x (metres). `side` (+1 / -1) picks the face for a point on the cut
  /// (|xb| <= 1e-9 r behind the front: theta = side * pi); 0 lets atan2 decide.
  Eigen::Vector3d displacement(const Eigen::Vector3d& x, int side = 0) const;
};

/// Rigid motion u(x) = t + w x (x - centre) of one piece of a body.
struct RigidMotion {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();  ///< small rotation vector, radians
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d displacement(const Eigen::Vector3d& x) const {
    return translation + rotation.cross(x - centre);
  }
};

}  // namespace xfem
