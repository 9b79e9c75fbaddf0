// bench_core: the simulator core alone (no ROS), one thread. Drives a wandering robot for a
// number of simulated seconds with the scan (and optionally the depth camera) at given rates
// and prints one markdown table row:
//   | world | solids | scan Hz | depth | sim s | CPU s | RTF per CPU s | RTF wall | rays per CPU s
//   | collisions | load CPU s | load wall s | peak RSS MB |
//   bench_core [--world NAME|PATH] [--seconds S] [--scan-rate HZ] [--depth-rate HZ]
//              [--depth-size WxH] [--header]
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "bullet_turtlebot/simulation.hpp"
#include "bullet_turtlebot/shipped_worlds.hpp"
#include "bullet_turtlebot/world_spec.hpp"

namespace bt = bullet_turtlebot;

// CPU time of this process: the machine may be shared, so RTF per CPU second is the figure
// that means "one core".
static double cpu_seconds() {
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// Peak resident memory of this program, MB. Not getrusage's ru_maxrss: after fork and exec
// that reports the parent's peak when it was larger (a benchmark script that has just
// generated a large world).
static double peak_rss_mb() {
  std::FILE* status = std::fopen("/proc/self/status", "r");
  if (!status) return NAN;
  char line[256];
  double kb = NAN;
  while (std::fgets(line, sizeof line, status)) {
    if (std::sscanf(line, "VmHWM: %lf kB", &kb) == 1) break;
  }
  std::fclose(status);
  return kb / 1024.0;
}

int main(int argc, char** argv) {
  std::string world_arg = "maze";
  double seconds = 300.0, scan_rate = 10.0, depth_rate = 0.0;
  int depth_w = 640, depth_h = 480;
  bool header = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : "";
    if (a == "--world") world_arg = v, ++i;
    else if (a == "--seconds") seconds = std::atof(v), ++i;
    else if (a == "--scan-rate") scan_rate = std::atof(v), ++i;
    else if (a == "--depth-rate") depth_rate = std::atof(v), ++i;
    else if (a == "--depth-size") std::sscanf(v, "%dx%d", &depth_w, &depth_h), ++i;
    else if (a == "--header") header = true;
    else {
      std::fprintf(stderr, "bench_core: unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  world_arg = bt::resolve_world_path(world_arg, bt::shipped_worlds_dir());
  // Loading: reading the image, merging its cells into boxes, building Bullet's tree.
  const auto t_load = std::chrono::steady_clock::now();
  const double cpu_load = cpu_seconds();
  bt::WorldSpec spec;
  try {
    spec = bt::load_world_file(world_arg);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_core: %s\n", e.what());
    return 1;
  }
  auto world = std::make_shared<const bt::World>(spec);
  const double load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_load).count();
  const double load_cpu_s = cpu_seconds() - cpu_load;
  bt::SimulationConfig config;
  bt::Simulation sim(world, config, spec.has_start ? spec.start : bt::Pose2D{});
  bt::LaserConfig laser;
  laser.noise = 0.003;
  laser.noise_quadratic = 0.0019;
  bt::CameraConfig camera;
  camera.width = depth_w;
  camera.height = depth_h;

  const long steps = std::lround(seconds / config.step);
  const long scan_period = scan_rate > 0 ? std::max(1L, std::lround(1.0 / (scan_rate * config.step))) : 0;
  const long depth_period = depth_rate > 0 ? std::max(1L, std::lround(1.0 / (depth_rate * config.step))) : 0;
  std::vector<float> ranges, depth;
  double rays = 0;
  double turn_until = -1.0, turn_dir = 1.0;
  unsigned rng = 12345;
  std::uint64_t collisions = 0;
  const double cpu_start = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  for (long i = 1; i <= steps; ++i) {
    // A wanderer: drive until something is within 0.8 m ahead, then turn for a while.
    if (i % 10 == 0) {
      if (sim.now() < turn_until) sim.command(0.0, 1.5 * turn_dir);
      else sim.command(0.5, 0.0);
    }
    sim.step();
    if (sim.collisions() != collisions && sim.now() >= turn_until) {  // bumped: back off by turning
      collisions = sim.collisions();
      rng = rng * 1103515245u + 12345u;
      turn_until = sim.now() + 1.0 + (rng >> 16) % 100 / 50.0;
      turn_dir = (rng >> 8) & 1 ? 1.0 : -1.0;
    }
    if (scan_period && i % scan_period == 0) {
      bt::scan_ranges(*world, laser, sim.depth_sensor_pose(), &sim.sensor_rng(), &ranges);
      rays += laser.samples;
      float nearest = INFINITY;
      for (size_t k = 240; k < 400; ++k) nearest = std::min(nearest, std::abs(ranges[k]));
      if (nearest < 0.8f && sim.now() >= turn_until) {
        rng = rng * 1103515245u + 12345u;
        turn_until = sim.now() + 0.5 + (rng >> 16) % 100 / 50.0;
        turn_dir = (rng >> 8) & 1 ? 1.0 : -1.0;
      }
    }
    if (depth_period && i % depth_period == 0) {
      bt::render_depth(*world, camera, sim.depth_sensor_pose(), &depth);
      rays += static_cast<double>(depth_w) * depth_h;
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpu_seconds() - cpu_start;
  const std::string name = world_arg.substr(world_arg.find_last_of('/') + 1);
  if (header) {
    std::printf("| world | solids | scan Hz | depth | sim s | CPU s | RTF (sim s per CPU s) | RTF (wall) | rays per CPU s | collisions | load CPU s | load wall s | peak RSS MB |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  }
  const std::string depth_desc =
      depth_period ? std::to_string(depth_w) + "x" + std::to_string(depth_h) + " @ " +
                         std::to_string(static_cast<int>(depth_rate)) + " Hz"
                   : "off";
  std::printf("| %s | %zu | %g | %s | %.0f | %.2f | %.0f | %.0f | %.2e | %llu | %.2f | %.2f | %.1f |\n", name.c_str(),
              world->solids().size(), scan_rate, depth_desc.c_str(), seconds, cpu, seconds / cpu, seconds / wall,
              rays / cpu,
              static_cast<unsigned long long>(sim.collisions()), load_cpu_s, load_s, peak_rss_mb());
  return 0;
}
