#pragma once
/// \file
/// Root-to-leaf kinematics of the body tree [Branlard2019, §3.2–3.3; BranlardGeisler2022, eq. 1–3], written once
/// for any scalar type T (double or ADChunk); body in kinematics.hxx, instantiated in kinematics.cpp.
#include "src/base/skew.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {

/// Fills ws.basis (c, ċ, c̈, D of every body) and ws.frames (R, r, v, a, ω, ω̇, Jv, Jω of every body
/// frame, ground components).
/// \param[in] q, qd, qdd  all coordinates, frozen ones included (dim model.ndof())
/// \param[in] pass  an AD pass that reads only derivatives copies unmoved frames (AdPass)
template <class T>
void forwardKinematics(const Model& model, Workspace<T>& ws, const VecXT<T>& q, const VecXT<T>& qd, const VecXT<T>& qdd,
                       const AdPass& pass = {});

/// Rotation by angle phi about the unit axis n: R such that R v turns v about n.
template <class T>
Mat3T<T> axisRotation(const Vec3& n, const T& phi);

}  // namespace whirl
