#pragma once
/// \file
/// A beam FE model of two-node elements with full 6 × 6 sections (element6.hpp) in one body frame:
/// nodes along a (possibly curved) reference axis, each element with its sections at both ends in
/// body axes (already turned by the axis' tangent and the twist). Assembly of K, M, D over the
/// 6 × nnodes DOFs [u_x, u_y, u_z, θ_x, θ_y, θ_z] (index 6 × node + k, as beam_model.hpp), and the
/// modes of the model clamped at one node.
#include <vector>

#include <Eigen/Sparse>

#include "src/fem/element6.hpp"

namespace whirl::fem {

struct Beam6Element {
  int n1 = -1, n2 = -1;
  Section6 s1, s2;  ///< body axes, linear between
};

struct Beam6Model {
  std::vector<Vec3> nodes;  ///< body frame [m]
  std::vector<Beam6Element> elements;
  int ndof() const { return 6 * static_cast<int>(nodes.size()); }
};

struct Beam6Matrices {
  Eigen::SparseMatrix<double> K, M, D;  ///< stiffness, consistent mass, damping (all DOFs)
};

/// \throws InputError for an element with bad nodes or zero length.
Beam6Matrices assemble6(const Beam6Model& model);

/// Lowest modes of K φ = ω² M φ with every DOF of `clamped_node` held: ω² ascending [rad²/s²], vectors
/// over all DOFs (zero at the clamped node), M-orthonormal. M may be singular (sections without
/// rotary inertia): the problem is solved as M φ = ω⁻² K φ with K positive definite.
struct Modes6 {
  VecX omega2;
  MatX vectors;  ///< ndof × count
};
/// \throws ComputeError when the clamped K is not positive definite (a mechanism) or fewer than
///   `count` modes have mass.
Modes6 clampedModes6(const Beam6Matrices& mats, int clamped_node, int count);

}  // namespace whirl::fem
