#include "cli/replay_animation.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/output_files.hpp"
#include "cli/load.hpp"

namespace esc::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMostFrames = 600;   // 30 s at 20 frames per second
constexpr int kFramesPerSecond = 20;

// The program `name` on $PATH, or empty.
fs::path on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

// Runs `args` with its output into `log`; true when it exits with status 0.
bool run_tool(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return false;
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string tail_of(const fs::path& log) {
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text.size() > 600 ? "..." + text.substr(text.size() - 600) : text;
}

// The frames: each shows the path of the current epoch so far and the robot at its end (a
// group's every robot: a frame ends with a step's last robot).
std::vector<fs::path> write_frames(const report::TrajectoryFigure& figure, const fs::path& dir) {
  const std::size_t n = figure.steps.size();
  const std::size_t robots = eval::trace_robots(figure.steps);
  const std::size_t stride = (n / robots + kMostFrames - 1) / kMostFrames;
  std::vector<fs::path> frames;
  std::size_t epoch_begin = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && figure.steps[i].epoch != figure.steps[i - 1].epoch) epoch_begin = i;
    const bool epoch_end = i + 1 == n || figure.steps[i + 1].epoch != figure.steps[i].epoch;
    if ((i + 1) % robots != 0 || ((i / robots) % stride != 0 && !epoch_end)) continue;
    report::TrajectoryFigure frame = figure;
    frame.steps = figure.steps.subspan(epoch_begin, i - epoch_begin + 1);
    frames.push_back(dir / fmt::format("frame-{:05}.svg", frames.size()));
    app::write_atomically(frames.back(), report::trajectory_svg(frame));
  }
  return frames;
}

}  // namespace

std::optional<fs::path> write_animation(const report::TrajectoryFigure& figure, const fs::path& stem) {
  const fs::path ffmpeg = on_path("ffmpeg");
  const fs::path convert = ffmpeg.empty() ? on_path("convert") : fs::path();
  if (ffmpeg.empty() && convert.empty()) {
    complain("esc: error: --animate needs ffmpeg (Debian: ffmpeg) or ImageMagick's convert (Debian: imagemagick); "
             "neither is on PATH, so no animation was written (the SVG and CSV were)\n");
    return std::nullopt;
  }
  if (figure.steps.empty()) {
    complain("esc: error: no step to animate\n");
    return std::nullopt;
  }
  std::string pattern = (fs::temp_directory_path() / "esc-frames-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    complain("esc: error: cannot create a temporary directory for the frames\n");
    return std::nullopt;
  }
  const fs::path dir = pattern;
  const std::vector<fs::path> frames = write_frames(figure, dir);
  fs::path movie = fs::path(stem).concat(ffmpeg.empty() ? ".gif" : ".mp4");
  std::vector<std::string> args;
  if (!ffmpeg.empty()) {
    // Even sizes and 4:2:0 colour: what players and slide software read.
    args = {ffmpeg.string(), "-y", "-loglevel", "error", "-framerate", std::to_string(kFramesPerSecond),
            "-i", (dir / "frame-%05d.svg").string(), "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2,format=yuv420p",
            movie.string()};
  } else {
    args = {convert.string(), "-delay", std::to_string(100 / kFramesPerSecond), "-loop", "0"};
    for (const fs::path& f : frames) args.push_back(f.string());
    args.push_back(movie.string());
  }
  const bool ok = run_tool(args, dir / "tool.log");
  if (!ok) complain("esc: error: {} could not make {}:\n{}\n", args.front(), movie.string(), tail_of(dir / "tool.log"));
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (!ok) return std::nullopt;
  return movie;
}

}  // namespace esc::cli
