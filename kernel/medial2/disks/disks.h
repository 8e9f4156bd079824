// disks.h -- a planar shape given as a union of disks, as a value (3.3, the disk-union
// input of the exact axis).
//
// Computes nothing: the types the disk-union axis (disk_union_axis.h) takes and the
// disk-list reader (io/disk_list.h) returns. DiskListError is what both throw for a list
// that is not a valid input: "<source>:<line>: <problem>" or "<source>: <problem>".
// Contract: radii > 0 (the reader checks it; disks built in code must respect it).
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/format_error.h"

namespace grassfire {

struct Disk {
  mpq_class x, y, r;     // exact centre and radius
  std::size_t line = 0;  // 1-based line in the source (0 for disks built in code)
};

struct DiskList {
  std::string name;  // the file path or source name, used in messages
  std::vector<Disk> disks;
};

class DiskListError : public FormatError {  // support/format_error.h: the contract of what()
 public:
  using FormatError::FormatError;
};

}  // namespace grassfire
