// burn_field_file.h -- a burning field kept in a file: what `burn3d --field OUT` writes and
// `curves3d`, `paths3d` and `prune3d --field FILE` read instead of burning again (format
// grassfire-burn3d-field, docs/formats.md).
//
// Computes: the file of a discrete burning (burn3/discrete/discrete_burning.h: BT per vertex
// and Steiner point, the first arrival per link element, and the predecessors the burning
// paths follow), with the counts and the digest of the complex it was burned on; and the
// burning back from such a file, checked against the complex the reader loaded. Every
// double is written as its shortest round-trip decimal (JSON numbers; null for +infinity),
// so the burning read back is the one written, bit for bit, and every field built on it
// (burn3/discrete/discrete_burning_field.h) gives the same curves and paths as burning again.
// The digest (complex_digest) is FNV-1a 64 over the complex's exact vertex coordinates and
// R^2, its edges with their stratum and ignition rule, its triangles and its sheets count:
// two complexes with the same digest are, but for a hash collision, the same complex.
// Only a burning from the border ignition is written (no point sources): that is what the
// readers burn when they burn themselves.
// Contract: errors are FormatError naming the file and the problem: not a field file, a
// version, a member missing or of the wrong size, a complex that is not the one the file
// was burned on (counts, then digest), a method other than discrete. Nothing is returned then.
// Complexity: linear in the burning's size (graph points and link slots).
// Section: ch. 4 (Definitions 9-10), 5.1.2; docs/design.md 5.
#pragma once

#include <string>

#include "burn3/discrete/discrete_burning.h"
#include "complex3/medial_complex.h"

namespace grassfire {

// 16 hexadecimal digits (see above).
std::string complex_digest(const MedialComplex& mc);

// Writes the burning `d` of `mc` (input: the INPUT it came from, for the reader's messages)
// to `path`, whole or not at all (support/atomic_file.h). std::invalid_argument when `d`
// has point sources.
void write_burn_field(const MedialComplex& mc, const DiscreteBurning& d, const std::string& input,
                      const std::string& path);

// The burning in `path`, which must have been burned on `mc`.
DiscreteBurning read_burn_field(const std::string& path, const MedialComplex& mc);

}  // namespace grassfire
