#pragma once
/// \file
/// A Campbell diagram in one call: the sweep over the operating points (modal/campbell_sweep.hpp,
/// spread over MPI ranks under mpirun), the tracking of the modes into lines (modal/tracking.hpp) and
/// where a tracked line's damping is negative — what `whirl campbell` and the Python module's
/// `Model.campbell` both need.
#include <string>
#include <vector>

#include "modal/campbell.hpp"
#include "modal/campbell_sweep.hpp"
#include "modal/tracking.hpp"

namespace whirl {

struct CampbellDiagramOptions {
  SweepOptions sweep;
  TrackingOptions tracking;
  std::string title;  ///< CampbellDiagram::title (campbellTitle)
};

/// The diagram of `model` at `points`. Under mpirun the points and lines are on rank 0 only (empty on
/// the other ranks), identical to a one-rank run.
CampbellDiagram campbellDiagram(const Model& model, const std::vector<SweepPoint>& points,
                                const CampbellDiagramOptions& opt = {});

/// A tracked line with negative damping somewhere: at how many points, the lowest damping ratio and
/// the point where it is (index into CampbellDiagram::points). Rigid-body modes are left out.
struct LineInstability {
  std::string name;
  int points = 0;
  double lowest_damping = 0;
  std::size_t at = 0;
};
std::vector<LineInstability> lineInstabilities(const CampbellDiagram& d);

/// "Campbell diagram: " and the model's name up to its first sentence (ElastoDyn headers run long), or
/// the case file's name when that is empty or longer than 70 characters.
std::string campbellTitle(const Model& model, const std::string& case_path);

}  // namespace whirl
