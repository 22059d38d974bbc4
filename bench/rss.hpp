// SPDX-License-Identifier: Apache-2.0
// CPU time and peak resident-set growth of one piece of work (Linux): the
// measuring shared by the benchmarks.
#pragma once
#include <malloc.h>

#include <ctime>
#include <fstream>
#include <string>

namespace bench {

// A field of /proc/self/status, in bytes.
inline long status_bytes(const std::string& field) {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1)) * 1024;
  return 0;
}

// CPU seconds of this process. The measured code is single-threaded, so on
// an idle machine this is the wall time; on a busy one (other jobs sharing
// the cores) it is not inflated by waiting for a core.
inline double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Measurement {
  double seconds;  // CPU
  long peak_bytes;  // growth of the resident set during the work
};

// Runs `work` and measures it. Freed heap is returned to the OS first and the
// kernel's high-water mark reset, so the previous work does not hide or
// inflate this one's memory.
template <class Work>
Measurement measure(Work work) {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  const long before = status_bytes("VmRSS");
  const double start = cpu_seconds();
  work();
  const double seconds = cpu_seconds() - start;
  return {seconds, status_bytes("VmHWM") - before};
}

}  // namespace bench
