// SPDX-License-Identifier: Apache-2.0
// GROMACS XTC and TRR through libgromacs (Debian: libgromacs-dev,
// gromacs/fileio/trxio.h): read_first_frame / read_next_frame, coordinates
// in nm (A here), time in ps.
#include <filesystem>

#include <gromacs/fileio/oenv.h>
#include <gromacs/fileio/trxio.h>
#include <gromacs/trajectory/trajectoryframe.h>

#include "alpha/error.hpp"
#include "trajectory/coordinate_reader.hpp"

namespace molecule {
namespace {

class GromacsReader : public CoordinateReader {
public:
  explicit GromacsReader(const std::string& path) : path_(path) {
    // libgromacs ends the process on a file it cannot open: check first.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) == 0)
      throw alpha::Error(path + ": " + (std::filesystem::exists(path, ec) ? "empty or not a file" : "no such file"),
                         alpha::ErrorKind::BadInput);
    output_env_init_default(&oenv_);
    if (!read_first_frame(oenv_, &status_, path.c_str(), &frame_, TRX_NEED_X)) {
      close();
      throw alpha::Error(path + ": no frame with coordinates (not an XTC or TRR file, or truncated)",
                         alpha::ErrorKind::BadInput);
    }
    atoms_ = std::size_t(frame_.natoms);
  }
  ~GromacsReader() override { close(); }

  std::size_t atoms() const override { return atoms_; }

  std::optional<CoordinateFrame> next() override {
    if (!have_) {
      if (!status_ || !read_next_frame(oenv_, status_, &frame_)) return std::nullopt;
    }
    have_ = false;
    if (std::size_t(frame_.natoms) != atoms_)
      throw alpha::Error(path_ + ": frame at time " + std::to_string(frame_.time) + " has " +
                             std::to_string(frame_.natoms) + " atoms, the first " + std::to_string(atoms_),
                         alpha::ErrorKind::BadInput);
    CoordinateFrame f;
    f.time = frame_.bTime ? double(frame_.time) : 0.0;
    f.x.resize(atoms_);
    for (std::size_t i = 0; i < atoms_; ++i)
      f.x[i] = {10.0 * double(frame_.x[i][0]), 10.0 * double(frame_.x[i][1]), 10.0 * double(frame_.x[i][2])};
    return f;
  }

private:
  void close() {
    if (status_) close_trx(status_);
    status_ = nullptr;
    if (oenv_) output_env_done(oenv_);
    oenv_ = nullptr;
  }

  std::string path_;
  gmx_output_env_t* oenv_ = nullptr;
  t_trxstatus* status_ = nullptr;
  t_trxframe frame_{};
  bool have_ = true;  // the first frame is read and not yet returned
  std::size_t atoms_ = 0;
};

}  // namespace

std::unique_ptr<CoordinateReader> open_gromacs(const std::string& path) {
  return std::make_unique<GromacsReader>(path);
}

}  // namespace molecule
