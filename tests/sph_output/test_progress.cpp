// The progress line: its content, its ETA arithmetic, and silence when not on a terminal.
#include <catch2/catch.hpp>

#include <sstream>

#include "sph/output/progress.h"

using namespace soilsph::sph;

TEST_CASE("the progress line shows time, fraction, steps, elapsed time and ETA", "[progress]") {
  // A quarter of the simulated time in 10 s of wall time: 3 more quarters take 30 s.
  const std::string line = format_progress(0.05, 0.2, 1234, 10.0);
  CHECK(line.find("t = 0.0500 / 0.2000 s") != std::string::npos);
  CHECK(line.find("( 25%)") != std::string::npos);
  CHECK(line.find("steps 1234") != std::string::npos);
  CHECK(line.find("elapsed 10s") != std::string::npos);
  CHECK(line.find("ETA 30s") != std::string::npos);
  // 0.01 of 0.2 s after 187 s: 19 × 187 s = 3553 s = 59m13s; 3725 s = 1h02m.
  CHECK(format_progress(0.01, 0.2, 1, 187.0).find("elapsed 3m07s  ETA 59m13s") != std::string::npos);
  CHECK(format_progress(0.1, 0.2, 1, 3725.0).find("ETA 1h02m") != std::string::npos);
  CHECK(format_progress(0.0, 0.2, 0, 1.0).find("ETA ?") != std::string::npos);  // no rate yet
}

TEST_CASE("a disabled progress line writes nothing", "[progress]") {
  std::ostringstream out;
  {
    Progress progress(0.2, out, false);
    progress.update(0.1, 10);
    progress.finish();
  }
  CHECK(out.str().empty());
}

TEST_CASE("an enabled progress line redraws in place and ends with a newline", "[progress]") {
  std::ostringstream out;
  Progress progress(0.2, out, true);
  progress.min_interval = std::chrono::duration<double>(0);
  progress.update(0.1, 10);
  progress.update(0.2, 20);
  progress.finish();
  const std::string text = out.str();
  CHECK(text.front() == '\r');
  CHECK(text.back() == '\n');
  CHECK(text.find("steps 10") != std::string::npos);
  CHECK(text.rfind("steps 20") > text.find("steps 10"));
  progress.update(0.3, 30);  // after finish: nothing more
  CHECK(out.str() == text);
}

TEST_CASE("in a log, progress is a plain line at every tenth of the run and after a quiet minute",
          "[progress]") {
  std::ostringstream out;
  Progress progress(1.0, out, Progress::Style::Log);
  for (int k = 1; k <= 1000; ++k) progress.update(k * 1e-3, static_cast<std::size_t>(k));  // 0.001 ... 1 s
  progress.finish();
  const std::string text = out.str();
  std::size_t lines = 0;
  for (const char c : text) lines += c == '\n';
  CHECK(lines == 10);  // at 10 %, 20 %, ..., 100 %
  CHECK(text.find('\r') == std::string::npos);
  CHECK(text.find("progress: t = 0.1000 / 1.0000 s ( 10%)") == 0);
  std::ostringstream slow;
  Progress quiet(1.0, slow, Progress::Style::Log);
  quiet.log_interval = std::chrono::duration<double>(0);  // "a minute" has passed at every step
  quiet.update(0.001, 1);
  quiet.update(0.002, 2);
  CHECK(slow.str().find("steps 2") != std::string::npos);
}
