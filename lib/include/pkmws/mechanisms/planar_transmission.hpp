// Force transmission of a planar 3-DOF parallel mechanism ([Briot],
// "Определение критерия"; docs/theory/three_dof.md): each chain i transmits to the platform a
// force R_i r_i along a known line of action (unit direction r_i through a
// point Q_i). With the wrench w = [f; m] of the external load referred to the
// reference point P:
//
//   w = -A^T R,   R = -A^{-T} w,   A row i = f_i^T = [r_i^T, (Q_i - P) x r_i].
//
// The rows of A^{-T} (the columns of A^{-1}) are the twists t_i = [v_P,i; ω_i]
// of the platform when only actuator i is free, normalised so that
// r_i . v_i = 1 (v_i the velocity of Q_i). Pressure angle:
// cos α_i = |r_i . v_i| / |v_i|. Largest reaction for a force of norm f in
// any direction and a moment ±m at P: R_i,max = f |v_P,i| + |m| |ω_i|
// (= (γ_i f + |m| / d_i) / cos α_i, d_i the distance from Q_i to the
// instantaneous centre I_i of twist t_i, γ_i d_i = |P I_i|).
//
// The same A, with rows the unit wrenches of the constraint forces, is the
// "A" of the velocity relation A [v_P; ω] = B q̇ of every 3-DOF mechanism in
// this library (3-RPR, 3-RRP, 3-PRP): det A = 0 is the type-2 (parallel)
// singularity, where the three lines of action are concurrent or parallel.
//
// Units: lengths in the mechanism's unit, forces in N, moments in N·(unit).
#pragma once

#include <array>

#include <Eigen/Core>

#include "pkmws/mechanisms/mechanism.hpp"

namespace pkmws::mechanisms {

/// Line of action of the force that chain i transmits to the platform.
struct ActuationLine {
  Point point;      // Q_i: a point of the line fixed to the platform at this instant (e.g. B_i)
  Point direction;  // r_i: unit direction of the force
};

/// Platform twist referred to the reference point P: velocity of P and the
/// angular velocity (rad per unit time).
struct PlanarTwist {
  Point velocity;
  double omega = 0.0;
  /// Velocity of the platform point Q (P the reference point of the twist).
  Point velocity_at(Point reference, Point q) const {
    return {velocity.x - omega * (q.y - reference.y), velocity.y + omega * (q.x - reference.x)};
  }
};

struct Transmission {
  Point reference;                      // P
  std::array<ActuationLine, 3> lines;
  Eigen::Matrix3d A;                    // rows [r_i^T, (Q_i - P) x r_i]
  double determinant = 0.0;             // det A (a length), invariant under change of P
  bool singular = false;                // type 2: |det A| <= 1e-9 L (lines concurrent or parallel)
  std::array<PlanarTwist, 3> twists;    // columns of A^{-1}; infinite at a singularity
  std::array<double, 3> pressure_angle; // α_i in radians, in [0, pi/2]; pi/2 at a singularity
  std::array<double, 3> lever;          // d_i = |Q_i I_i| (infinity for a pure translation twist)
  std::array<double, 3> lever_ratio;    // γ_i = |P I_i| / d_i (1 for a pure translation twist)
};

/// The wrench matrix A of the three lines referred to `reference`.
Eigen::Matrix3d wrench_matrix(Point reference, const std::array<ActuationLine, 3>& lines);

/// Twists, pressure angles and levers of the three chains at a pose. The
/// singularity test is |det A| <= 1e-9 L, L the largest distance of a Q_i from
/// the centroid of the three (det A is a length; L = 1 unit when the Q_i coincide).
Transmission analyse_transmission(Point reference, const std::array<ActuationLine, 3>& lines);

/// R_i,max = f |v_P,i| + |m| |ω_i| for each chain (N); infinite at a singularity.
std::array<double, 3> reaction_max(const Transmission& t, const Load& load);

/// Reactions R = -A^{-T} w for one load: force `force` and moment `moment`
/// about the reference point (signed magnitudes along r_i).
std::array<double, 3> reactions(const Transmission& t, Point force, double moment);

}  // namespace pkmws::mechanisms
