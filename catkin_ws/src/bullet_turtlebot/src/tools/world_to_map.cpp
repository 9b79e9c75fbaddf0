// world_to_map: writes a world's ground-truth occupancy grid as a map_server map.
//   rosrun bullet_turtlebot world_to_map <world name|file.yaml> [-f NAME] [--resolution R]
//                                          [--margin M] [--min-height H]
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "bullet_turtlebot/occupancy_export.hpp"
#include "bullet_turtlebot/shipped_worlds.hpp"
#include "bullet_turtlebot/world_spec.hpp"

namespace {

int usage(const char* problem) {
  std::fprintf(stderr,
               "world_to_map: %s\nusage: world_to_map <world name|file.yaml> [-f NAME] [--resolution R] "
               "[--margin M] [--min-height H]\n  writes NAME.pgm and NAME.yaml (default NAME: map)\n",
               problem);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  namespace bt = bullet_turtlebot;
  std::string world, out = "map";
  double resolution = 0.05, margin = 0.5, min_height = 0.0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    // The option's argument, or nullptr when the option ends the command line.
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    if (arg == "-h" || arg == "--help") return usage("help"), 0;
    if (arg == "-f") {
      const char* v = value();
      if (!v || !*v) return usage("-f needs a base name (it writes NAME.pgm and NAME.yaml)");
      out = v;
    } else if (arg == "--resolution" || arg == "--margin" || arg == "--min-height") {
      const char* v = value();
      char* end = nullptr;
      const double number = v ? std::strtod(v, &end) : 0.0;
      if (!v || *end != '\0') return usage((arg + " needs a number").c_str());
      (arg == "--resolution" ? resolution : arg == "--margin" ? margin : min_height) = number;
    } else if (!arg.empty() && arg[0] == '-') {
      return usage(("unknown option " + arg).c_str());
    } else if (world.empty()) {
      world = arg;
    } else {
      return usage("more than one world given");
    }
  }
  if (world.empty()) return usage("no world given");
  if (!(resolution > 0) || !std::isfinite(resolution)) return usage("--resolution must be > 0 and finite");
  if (!(margin >= 0) || !std::isfinite(margin)) return usage("--margin must be >= 0 and finite (metres)");
  if (!std::isfinite(min_height)) return usage("--min-height must be a finite number (metres)");
  const std::filesystem::path folder = std::filesystem::path(out).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder)) {
    std::fprintf(stderr, "world_to_map: cannot write %s.pgm: folder %s does not exist (create it with: mkdir -p '%s')\n",
                 out.c_str(), folder.c_str(), folder.c_str());
    return 1;
  }
  world = bt::resolve_world_path(world, bt::shipped_worlds_dir());
  try {
    const bt::World w(bt::load_world_file(world));
    const bt::MapImage map = bt::rasterize_world(w, resolution, margin, min_height);
    bt::write_map(map, out);
    std::printf("wrote %s.yaml and %s.pgm: %dx%d cells at %g m, origin (%g, %g)\n", out.c_str(), out.c_str(),
                map.image.width, map.image.height, resolution, map.origin.x, map.origin.y);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "world_to_map: %s\n", e.what());
    return 1;
  }
  return 0;
}
