// burn3d_field.h -- the burning field a 3D analysis works on (curves3d, paths3d, prune3d),
// from the same INPUT and method names as burn3d (pipeline/burn3d_methods.h).
//
// Builds, from INPUT (pipeline/complex_input.h), the validated MedialComplex and a
// BurningField over it (burn3/burning_field.h): `discrete` runs the baseline
// (burn3/discrete/discrete_burning.h) with the Steiner spacing h (default: default_burn_spacing,
// 1/100 of the bounding box diagonal) and wraps it (burn3/discrete/discrete_burning_field.h);
// `exact` runs the window-propagation engine from the border ignition
// (burn3/exact/exact_burning.h; refused on complexes it cannot burn as Definition 9 unless
// singular_walls) and wraps it (burn3/exact/exact_burning_field.h), with the spacing the
// spacing of the edge points at which medial curves are traced. With a field file (burn3d
// --field, io/burn_field_file.h) the discrete burning is read from it, after checking it was
// burned on INPUT's complex, instead of burning again: the same field, bit for bit, so the
// same curves, paths and pruned axes. The program's commands and
// the Python module call this, so both give the same field. A new method is a new branch
// here that returns another BurningField.
// Progress: the stages (loading, burning with its fraction, exact propagation) on stderr as
// the verbosity says (support/progress.h), named "<command> <input>".
// Contract: errors are exceptions naming the input and the problem (std::invalid_argument
// for a bad method, spacing or point budget, or options a field file contradicts; a
// FormatError naming the field file when it is not one or belongs to another complex);
// nothing is returned then.
// Complexity: the builder's and the method's.
// Section: ch. 4 (Definitions 9-10), 5.1.2.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "burn3/burning_field.h"
#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "medial3/mesh/mesh_repair.h"

namespace grassfire {

struct FieldSetup {
  std::string input;                // load_complex's INPUT
  std::string method = "discrete";  // "discrete" or "exact"
  bool mesh_is_complex = false;
  bool singular_walls = false;      // exact only
  std::optional<double> spacing;
  std::uint64_t max_points = 50'000'000;  // discrete only
  std::string command = "burn3d";   // names the command in notes
  MeshRepairOptions repair;         // a defective mesh INPUT (medial3/mesh/mesh_repair.h)
  // A burning burn3d --field wrote (io/burn_field_file.h), read instead of burning: it must
  // have been burned on INPUT's complex; method discrete; its spacing is the field's.
  std::optional<std::string> field_file;
};

struct FieldRun {
  std::unique_ptr<MedialComplex> complex;
  std::unique_ptr<DiscreteBurning> burning;  // the discrete method's graph values
  std::unique_ptr<ExactBurning> exact;       // the exact method's engine
  std::unique_ptr<BurningField> field;
  double spacing = 0;
  // Per vertex, a certified bound on |BT - exact BT| (exact method); empty otherwise.
  std::vector<double> vertex_bt_error;
};

FieldRun load_burning_field(const FieldSetup& setup);

}  // namespace grassfire
