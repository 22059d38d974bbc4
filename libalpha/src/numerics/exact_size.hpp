// SPDX-License-Identifier: Apache-2.0
// Exact sizes of simplices as GMP fractions: internal to libalpha (the
// public alpha/sizes.hpp carries no GMP), used by the spectrum sort and the
// tests.
#pragma once
#include <gmpxx.h>

#include <cstdint>
#include <optional>

namespace alpha {

// Defined in alpha/sizes.hpp, whose source (sizes.cpp) computes the
// functions below: this header includes it not, so the two point one way.
struct Simplex;
class SizeKernel;

// An exact size as an unreduced fraction: num / den * 4^unit, den != 0.
// Cheaper than exact_size (no gcd) when sizes are only compared.
struct ExactSize {
  mpz_class num, den;
  int unit = 0;
};
// Exact sign of a - b.
int compare_exact(const ExactSize& a, const ExactSize& b);

ExactSize exact_fraction(const SizeKernel& kernel, const Simplex& s);

// The exact size as N / D (D > 0) in integers below 2^53, where doubles
// compute it exactly (integer input and small simplices: grids, no GMP);
// nothing otherwise.
struct SmallFraction {
  std::int64_t num, den;
};
std::optional<SmallFraction> small_fraction(const SizeKernel& kernel, const Simplex& s);
int compare_small(const SmallFraction& a, const SmallFraction& b);  // exact sign of a - b
// The exact size, reduced.
mpq_class exact_size(const SizeKernel& kernel, const Simplex& s);

// SizeKernel::rounded_size in its two ways: the nearest double decided in
// double-double arithmetic, or nothing where that cannot be certain (a
// value near or on a midpoint of two doubles, a near-degenerate simplex,
// values outside its range); and from the exact fraction, always.
// fma = false: Dekker's products even where the processor has an FMA (the
// tests compare the two ways).
std::optional<double> rounded_filtered(const SizeKernel& kernel, const Simplex& s, bool fma = true);
double rounded_exact(const SizeKernel& kernel, const Simplex& s);

}  // namespace alpha
