/* SPDX-License-Identifier: Apache-2.0
 * Preloaded into `gmx mdrun` (LD_PRELOAD) on CPUs that execute rdtscp but
 * do not announce it in CPUID (some virtual machines): Debian's GROMACS
 * (2022) is built to use rdtscp and refuses to start when CPUID lacks the
 * bit. Here gmx::CpuInfo::detect() returns a CpuInfo whose support level is
 * "none" (nothing detected), the case in which mdrun warns and goes on. The
 * test runs rdtscp itself first, so this is used only where it works.
 * Only libgromacs's exported symbols are named: the constructor, and the
 * detect() this replaces (its result returned through the hidden pointer
 * of the x86-64 ABI, CpuInfo not being trivially copyable). The
 * constructor leaves the support level, CpuInfo's first member (an int
 * enum, "none" = 0), unset: set here. */
void _ZN3gmx7CpuInfoC1Ev(void* self);

void* _ZN3gmx7CpuInfo6detectEv(void* result) {
  _ZN3gmx7CpuInfoC1Ev(result);
  *(int*)result = 0;
  return result;
}
