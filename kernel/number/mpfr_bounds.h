// mpfr_bounds.h -- a pair of MPFR numbers used as a certified enclosure [lo, hi].
//
// RAII ownership of two mpfr_t at one precision; callers fill them with directed
// rounding (lo rounded down, hi rounded up). sign() reads the certified sign.
#pragma once

#include <mpfr.h>

#include "number/interval.h"

namespace grassfire {

struct MpfrBounds {
  mpfr_t lo, hi;
  explicit MpfrBounds(long bits) {
    mpfr_init2(lo, bits);
    mpfr_init2(hi, bits);
  }
  ~MpfrBounds() {
    mpfr_clear(lo);
    mpfr_clear(hi);
  }
  MpfrBounds(const MpfrBounds&) = delete;
  MpfrBounds& operator=(const MpfrBounds&) = delete;
  // +1 / -1 when the enclosure excludes zero, 0 when it is the point zero, else kUndecided.
  int sign() const {
    if (mpfr_sgn(lo) > 0) return 1;
    if (mpfr_sgn(hi) < 0) return -1;
    if (mpfr_zero_p(lo) && mpfr_zero_p(hi)) return 0;
    return kUndecided;
  }
};

}  // namespace grassfire
