// SPDX-License-Identifier: Apache-2.0
// The frame sources of molecule/track.hpp: the models of one file, a list
// of structure files, trajectory files, coordinates given by a function.
#include <utility>

#include "alpha/error.hpp"
#include "alpha/input_file.hpp"
#include "molecule/track.hpp"
#include "trajectory/coordinate_reader.hpp"
#include "trajectory/gro_topology.hpp"
#include "trajectory/pdb_models.hpp"
#include "util/gunzip.hpp"

namespace molecule {
namespace {

// The models of a multi-model file, then each further structure file's.
// A PDB file's models are parsed one at a time (PdbModels); an mmCIF
// file's all at once.
class StructureFrames : public FrameSource {
public:
  StructureFrames(std::vector<std::string> files, const StructureOptions& options)
      : files_(std::move(files)), options_(options) {
    options_.model = 0;  // each model text holds one
  }

  std::optional<Frame> next() override {
    while (model_ == count_) {
      if (file_ == files_.size()) return std::nullopt;
      name_ = files_[file_++];
      try {
        text_ = alpha::read_input_file(name_);
      } catch (const alpha::Error& e) {
        throw StructureError(e.what(), e.kind());
      }
      pdb_.reset();
      parsed_.clear();
      unzipped_.clear();
      if (is_gzip(text_)) {
        try {
          unzipped_ = gunzip(text_, name_, options_.max_input_mib << 20);
        } catch (const alpha::Error& e) {
          throw StructureError(e.what(), e.kind());
        }
      }
      if (!is_mmcif_name(name_)) pdb_.emplace(unzipped_.empty() ? text_ : unzipped_);
      if (pdb_ && pdb_->size() > 1) {
        count_ = pdb_->size();
      } else {
        pdb_.reset();
        parsed_ = parse_models(text_, name_, options_);
        count_ = parsed_.size();
      }
      model_ = 0;
    }
    Frame f;
    f.index = index_;
    f.time = double(index_++);
    f.structure = pdb_ ? model(model_) : std::move(parsed_[model_]);
    f.name = count_ > 1 ? name_ + " model " + std::to_string(f.structure.report.model) : name_;
    ++model_;
    return f;
  }

private:
  // Model k of a multi-model PDB file, parsed from its text (decompressed:
  // parsed under the name without .gz, messages given the file's name).
  Structure model(std::size_t k) const {
    if (unzipped_.empty() || !name_.ends_with(".gz")) return parse_structure(pdb_->text(k), name_, options_);
    const std::string plain = name_.substr(0, name_.size() - 3);
    try {
      Structure s = parse_structure(pdb_->text(k), plain, options_);
      s.report.gzipped = true;
      return s;
    } catch (const StructureError& e) {
      const std::string message = e.what();
      throw StructureError(message.starts_with(plain) ? name_ + message.substr(plain.size()) : message, e.kind());
    }
  }

  static bool is_mmcif_name(std::string name) {
    if (name.ends_with(".gz")) name.resize(name.size() - 3);
    return name.ends_with(".cif") || name.ends_with(".mmcif");
  }

  std::vector<std::string> files_;
  StructureOptions options_;
  std::size_t file_ = 0, model_ = 0, count_ = 0, index_ = 0;
  std::string text_, unzipped_, name_;  // of the file being read (its bytes, decompressed if gzip)
  std::optional<PdbModels> pdb_;     // its models, when a multi-model PDB file
  std::vector<Structure> parsed_;    // else its models, parsed
};

// Coordinates of every atom of the topology's model, in its file order,
// one frame at a time from a function.
class FunctionFrames : public FrameSource {
public:
  FunctionFrames(Structure topology, CoordinatesFunction next)
      : topology_(std::move(topology)), next_(std::move(next)) {}

  std::optional<Frame> next() override {
    std::optional<TimedCoordinates> c = next_();
    if (!c) return std::nullopt;
    const std::size_t need = topology_.report.atoms_in_model;
    if (c->x.size() != need)
      throw alpha::Error("frame " + std::to_string(index_) + " has " + std::to_string(c->x.size()) +
                             " atoms, but the topology has " + std::to_string(need),
                         alpha::ErrorKind::BadInput);
    Frame f;
    f.index = index_;
    f.time = c->time.value_or(double(index_));
    f.time_in_ps = c->time.has_value();
    f.name = "frame " + std::to_string(index_++);
    f.structure = topology_;
    for (Atom& a : f.structure.atoms) a.position = c->x[a.file_index];
    return f;
  }

private:
  Structure topology_;
  CoordinatesFunction next_;
  std::size_t index_ = 0;
};

// The frames of trajectory files, their atoms those of the topology.
class TrajectoryFrames : public FrameSource {
public:
  TrajectoryFrames(Structure topology, std::string topology_name, std::vector<std::string> files)
      : topology_(std::move(topology)), topology_name_(std::move(topology_name)), files_(std::move(files)) {}

  std::optional<Frame> next() override {
    std::optional<CoordinateFrame> c;
    while (!(reader_ && (c = reader_->next()))) {
      if (file_ == files_.size()) return std::nullopt;
      name_ = files_[file_++];
      reader_ = open_trajectory(name_);
      in_file_ = 0;
      const std::size_t need = topology_.report.atoms_in_model;
      if (reader_->atoms() != need)
        throw alpha::Error(name_ + ": " + std::to_string(reader_->atoms()) + " atoms, but the topology " +
                               topology_name_ + " has " + std::to_string(need),
                           alpha::ErrorKind::BadInput);
    }
    Frame f;
    f.index = index_++;
    f.time = c->time;
    f.time_in_ps = true;
    f.name = name_ + " frame " + std::to_string(in_file_++);
    f.structure = topology_;
    for (Atom& a : f.structure.atoms) a.position = c->x[a.file_index];
    return f;
  }

private:
  Structure topology_;
  std::string topology_name_;
  std::vector<std::string> files_;
  std::size_t file_ = 0, index_ = 0, in_file_ = 0;
  std::unique_ptr<CoordinateReader> reader_;
  std::string name_;
};

}  // namespace

Structure read_topology(const std::string& file, const StructureOptions& options) {
  if (!is_gro_file(file)) return read_structure(file, options);
  std::string text;
  try {
    text = alpha::read_input_file(file);
  } catch (const alpha::Error& e) {
    throw StructureError(e.what(), e.kind());
  }
  return parse_structure(gro_as_pdb(text, file), file, options);
}

std::unique_ptr<FrameSource> open_frames(const std::string& topology, const std::vector<std::string>& trajectories,
                                         const StructureOptions& options) {
  if (!trajectories.empty() && is_trajectory_file(trajectories.front())) {
    for (const std::string& t : trajectories)
      if (!is_trajectory_file(t))
        throw alpha::Error(t + ": not a trajectory file like " + trajectories.front() + " (.dcd, .xtc, .trr)",
                           alpha::ErrorKind::BadInput);
    return std::make_unique<TrajectoryFrames>(read_topology(topology, options), topology, trajectories);
  }
  std::vector<std::string> files{topology};
  for (const std::string& t : trajectories) {
    if (!is_structure_file(t))
      throw alpha::Error(t + ": neither a structure file (.pdb .ent .cif .mmcif, optionally .gz) nor a trajectory (" +
                             std::string(is_trajectory_file("x.xtc") ? ".dcd .xtc .trr" : ".dcd") + ")",
                         alpha::ErrorKind::BadInput);
    files.push_back(t);
  }
  return std::make_unique<StructureFrames>(std::move(files), options);
}

std::unique_ptr<FrameSource> frames_from_function(Structure topology, CoordinatesFunction next) {
  return std::make_unique<FunctionFrames>(std::move(topology), std::move(next));
}

}  // namespace molecule
