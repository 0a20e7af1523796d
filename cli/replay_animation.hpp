#pragma once
// An animation of a replay (`esc replay --animate`): frames drawn as the trajectory picture
// is (runtime/report/trajectory_svg.hpp), the path growing step by step and the robot where
// it is, turned into a video by a tool esc does not link: ffmpeg (Debian: ffmpeg; its SVG
// decoder is librsvg) for an MP4, else ImageMagick's convert (Debian: imagemagick) for a
// GIF. Without either, esc says so and writes no animation.
#include <filesystem>
#include <optional>

#include "runtime/report/trajectory_svg.hpp"

namespace esc::cli {

// Writes `stem`.mp4 or `stem`.gif; returns its path, or nullopt after printing why not.
std::optional<std::filesystem::path> write_animation(const report::TrajectoryFigure& figure,
                                                     const std::filesystem::path& stem);

}  // namespace esc::cli
