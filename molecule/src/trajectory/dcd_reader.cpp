// SPDX-License-Identifier: Apache-2.0
// CHARMM/NAMD/X-PLOR DCD: Fortran unformatted records, each framed by its
// byte count (4 bytes) before and after, in either byte order (the first
// count, 84, tells which):
//   header   "CORD", 20 int32 control words (1: frames, 2: first step,
//            3: steps between frames, 10: time step (float, AKMA units;
//            a double over words 10-11 for X-PLOR files, whose word 20 is
//            0), 11: unit cell present, 12: fourth dimension, 20: CHARMM
//            version)
//   title    int32 count, count lines of 80 characters
//   atoms    int32 N
//   frames   [unit cell: 6 doubles] X (N float32), Y, Z [, W]
#include <bit>
#include <byteswap.h>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "alpha/error.hpp"
#include "trajectory/coordinate_reader.hpp"

namespace molecule {
namespace {

constexpr double kAkmaPicoseconds = 0.04888821;  // CHARMM's time unit, ps

class DcdReader : public CoordinateReader {
public:
  explicit DcdReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) fail("cannot open the file", alpha::ErrorKind::BadInput);
    std::uint32_t first = 0;
    if (!in_.read(reinterpret_cast<char*>(&first), 4))
      fail("file is empty or shorter than a DCD header", alpha::ErrorKind::BadInput);
    swap_ = first != 84;
    if (swap_ && bswap_32(first) != 84)
      fail("not a DCD file (its first record is not 84 bytes)", alpha::ErrorKind::BadInput);
    in_.seekg(0);
    const std::string header = record("the header");
    if (header.size() != 84 || header.compare(0, 4, "CORD") != 0)
      fail("not a DCD file (no CORD header)", alpha::ErrorKind::BadInput);
    const auto word = [&](int k) { return int32(header.data() + 4 * k); };  // 1-based after "CORD"
    first_step_ = word(2);
    step_ = word(3);
    const bool charmm = word(20) != 0;
    if (charmm) {
      float dt;
      std::memcpy(&dt, header.data() + 40, 4);
      if (swap_) dt = std::bit_cast<float>(bswap_32(std::bit_cast<std::uint32_t>(dt)));
      delta_ = dt;
      cell_ = word(11) != 0;
      four_d_ = word(12) != 0;
    } else {
      std::uint64_t bits;
      std::memcpy(&bits, header.data() + 40, 8);
      delta_ = std::bit_cast<double>(swap_ ? bswap_64(bits) : bits);
    }
    record("the title");
    const std::string n = record("the atom count");
    if (n.size() != 4)
      fail("the atom count record is " + std::to_string(n.size()) + " bytes, not 4", alpha::ErrorKind::BadInput);
    const std::int32_t atoms = int32(n.data());
    if (atoms <= 0) fail("atom count " + std::to_string(atoms), alpha::ErrorKind::BadInput);
    atoms_ = std::size_t(atoms);
  }

  std::size_t atoms() const override { return atoms_; }

  std::optional<CoordinateFrame> next() override {
    if (in_.peek() == std::char_traits<char>::eof()) return std::nullopt;
    const std::string where = "frame " + std::to_string(frame_);
    if (cell_) record(where + " (unit cell)");
    CoordinateFrame f;
    f.x.resize(atoms_);
    for (int axis = 0; axis < 3; ++axis) {
      const std::string r = record(where);
      if (r.size() != 4 * atoms_)
        fail(where + ": a coordinate record of " + std::to_string(r.size()) + " bytes, not " +
                 std::to_string(4 * atoms_) + " (" + std::to_string(atoms_) + " atoms)",
             alpha::ErrorKind::BadInput);
      for (std::size_t i = 0; i < atoms_; ++i) {
        std::uint32_t bits;
        std::memcpy(&bits, r.data() + 4 * i, 4);
        const double v = std::bit_cast<float>(swap_ ? bswap_32(bits) : bits);
        (axis == 0 ? f.x[i].x : axis == 1 ? f.x[i].y : f.x[i].z) = v;
      }
    }
    if (four_d_) record(where + " (fourth dimension)");
    f.time = double(first_step_ + std::int64_t(frame_) * step_) * delta_ * kAkmaPicoseconds;
    ++frame_;
    return f;
  }

private:
  [[noreturn]] void fail(const std::string& what, alpha::ErrorKind kind) const {
    throw alpha::Error(path_ + ": " + what, kind);
  }
  std::int32_t int32(const char* p) const {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return std::int32_t(swap_ ? bswap_32(v) : v);
  }
  // One Fortran record's bytes.
  std::string record(const std::string& what) {
    char count[4];
    if (!in_.read(count, 4)) fail("truncated in " + what + " (no record length)", alpha::ErrorKind::BadInput);
    const std::int32_t n = int32(count);
    if (n < 0 || n > (1 << 30))
      fail("corrupt record length " + std::to_string(n) + " in " + what, alpha::ErrorKind::BadInput);
    std::string bytes(std::size_t(n), '\0');
    if (!in_.read(bytes.data(), n))
      fail("truncated in " + what + " (" + std::to_string(n) + "-byte record cut short)", alpha::ErrorKind::BadInput);
    char end[4];
    if (!in_.read(end, 4)) fail("truncated in " + what + " (no closing record length)", alpha::ErrorKind::BadInput);
    if (int32(end) != n)
      fail("corrupt record in " + what + " (lengths " + std::to_string(n) + " and " + std::to_string(int32(end)) + ")",
           alpha::ErrorKind::BadInput);
    return bytes;
  }

  std::string path_;
  std::ifstream in_;
  bool swap_ = false, cell_ = false, four_d_ = false;
  std::int64_t first_step_ = 0, step_ = 1;
  double delta_ = 0;
  std::size_t atoms_ = 0, frame_ = 0;
};

}  // namespace

std::unique_ptr<CoordinateReader> open_dcd(const std::string& path) { return std::make_unique<DcdReader>(path); }

}  // namespace molecule
