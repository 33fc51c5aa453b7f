#pragma once
/// @file
/// Frames of an SPH run written while it runs: DIR/frames/frame_NNNNNN.h5 (one HDF5 file per frame),
/// DIR/frames.h5 (an HDF5 index whose group /frame_NNNNNN is an external link to that file, so that
/// readers see one file of frames) and DIR/frames.xdmf (the XDMF index ParaView opens as a time
/// series of particle clouds). The layout is described in docs/reference/output-formats.md.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "sph/output/frame.h"

namespace soilsph::sph {

/// Writes the frames (reached as /frame_000000/{position,velocity,sxx,...} + attribute time through
/// DIR/frames.h5) and DIR/frames.xdmf (a temporal collection of Polyvertex grids ParaView opens).
/// Each frame holds the positions and only the datasets of the selected fields (FieldSet).
/// Every file is written whole to NAME.tmp and renamed into place, the frame before the indexes that
/// point at it: HDF5 1.10 has no journal, and appending to one file that a kill -9 interrupts can
/// leave it, earlier frames included, unreadable (measured: 2 of 40 random kills). Now any kill
/// leaves every file that exists complete. The writer takes no HDF5 file lock: viewers (ParaView,
/// h5py) can read the frames of a running simulation, and a viewer that keeps a file open does not
/// stop the run.
class FrameWriter {
 public:
  /// Creates DIR if needed, removes DIR/frames/ of an earlier run, and writes empty indexes. Every
  /// frame holds the
  /// positions and the datasets of `fields` (default: all), and the XDMF index lists only those.
  /// `dimension` 2 or 3: the frames' (Frame::dimension), which the conventions of the indexes state.
  explicit FrameWriter(const std::filesystem::path& dir, FieldSet fields = FieldSet::all(), int dimension = 2);
  /// Continues the frames of DIR (a resumed run): keeps those up to time `last_kept` and deletes the
  /// later ones, which a run wrote after the checkpoint it is resumed from. Throws std::runtime_error
  /// if DIR/frames.h5 cannot be opened.
  static FrameWriter continuing(const std::filesystem::path& dir, FieldSet fields, double last_kept,
                                int dimension = 2);
  FrameWriter(FrameWriter&&) = default;
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  /// Appends a frame and rewrites the XDMF index; throws std::invalid_argument if the spans of the
  /// positions and of the selected fields differ in length (the spans of the other fields are not
  /// read) or the frame's dimension is not the writer's, and std::runtime_error if HDF5 or the file
  /// system fails. A 3D frame writes positions and velocities (x, y, z) and the stress components
  /// sxx, syy, szz, sxy, sxz, syz; a 2D frame (x, y, 0) and sxx, syy, szz, sxy.
  void write(const Frame& frame);

  /// Number of frames written so far.
  std::size_t frames() const { return frames_.size(); }
  /// The fields written besides the positions.
  FieldSet fields() const { return fields_; }
  /// 2 or 3.
  int dimension() const { return dimension_; }
  /// DIR/frames.h5.
  const std::filesystem::path& h5_path() const { return h5_path_; }
  /// DIR/frames.xdmf.
  const std::filesystem::path& xdmf_path() const { return xdmf_path_; }

 private:
  struct FrameEntry {
    double time;
    std::size_t particles;
    int state_variables = 0;  ///< statev_1 … of the frame (Frame::state_variable_count)
    bool ids = false;  ///< the frame holds the particles' ids (a frame of a run resumed from an older one may not)
  };
  void write_xdmf() const;
  void write_index() const;
  std::filesystem::path frame_path(std::size_t index) const;
  struct Continuing {};
  FrameWriter(const std::filesystem::path& dir, FieldSet fields, int dimension, Continuing);

  std::filesystem::path h5_path_, xdmf_path_;
  FieldSet fields_;
  int dimension_;
  std::vector<FrameEntry> frames_;
};

}  // namespace soilsph::sph
