// disk_list.h -- the disk-list text format: a planar shape given as a union of disks.
//
// Format (one disk per line, the input of medial2/disks/disk_union_axis.h and of
// `grassfire edf2d --disks FILE`):
//     # comment lines and blank lines are ignored; '#' also starts a trailing comment
//     x y r
// x, y (centre) and r (radius) are decimal numbers, [+-]digits[.digits][e[+-]digits] or
// [+-].digits[...]; they are read exactly as the rationals they write (0.1 is 1/10, not
// the double nearest to it), so the union is exactly the one in the file. Fields are
// separated by spaces, tabs or commas.
// Errors (DiskListError; what() is "<file>:<line>: <problem>"): a line without exactly
// three numbers, a field that is not such a decimal (nan, inf, 0x1p3, 1/2, ...), a number
// of more than 1000 digits or with an exponent beyond +-300, r <= 0, and a file without any
// disk.
// Accepted on purpose, and handled by the axis builder: a disk inside another or a
// repeated disk (it adds nothing to the union and is reported as covered); disjoint
// groups of disks (the union is disconnected and its medial axis is a forest, one tree
// or cyclic part per component). Degenerate unions (two circles touching at one
// boundary point, three circles through one boundary point) are rejected by the builder
// with the line numbers of the disks involved.
// Complexity: O(total characters).
#pragma once

#include <gmpxx.h>

#include <string>

#include "medial2/disks/disks.h"

namespace grassfire {

// Parses `text`; `source` names it in messages.
DiskList parse_disk_list(const std::string& text, const std::string& source);
// Reads and parses a file; an unreadable file is a DiskListError naming the path.
DiskList read_disk_list(const std::string& path);

}  // namespace grassfire
