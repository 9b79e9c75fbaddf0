#include "bullet_turtlebot/world_spec.hpp"

#include <sys/stat.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "bullet_turtlebot/image_io.hpp"

namespace bullet_turtlebot {
namespace {

class Parser {
 public:
  explicit Parser(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& problem) const {
    throw WorldFileError("world file '" + source_ + "': " + problem);
  }

  double number(const YAML::Node& node, const std::string& what) const {
    if (!node.IsScalar()) fail("'" + what + "' must be a number");
    double value;
    try {
      value = node.as<double>();
    } catch (const YAML::Exception&) {
      fail("'" + what + "' must be a number, got '" + node.Scalar() + "'");
    }
    if (!std::isfinite(value)) fail("'" + what + "' must be finite");
    return value;
  }

  double positive(const YAML::Node& node, const std::string& what) const {
    const double value = number(node, what);
    if (value <= 0) fail("'" + what + "' must be > 0, got " + node.Scalar());
    return value;
  }

  std::vector<double> numbers(const YAML::Node& node, const std::string& what, size_t min_size,
                              size_t max_size) const {
    if (!node.IsSequence() || node.size() < min_size || node.size() > max_size) {
      fail("'" + what + "' must be a list of " +
           (min_size == max_size ? std::to_string(min_size)
                                 : std::to_string(min_size) + " to " + std::to_string(max_size)) +
           " numbers");
    }
    std::vector<double> out;
    for (size_t i = 0; i < node.size(); ++i) out.push_back(number(node[i], what + "[" + std::to_string(i) + "]"));
    return out;
  }

  Color color(const YAML::Node& node, const std::string& what, Color fallback) const {
    if (!node) return fallback;
    const auto c = numbers(node, what, 3, 3);
    for (double v : c) {
      if (v < 0 || v > 1) fail("'" + what + "' components must lie in [0, 1]");
    }
    return Color{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2])};
  }

  // A place or a length in metres. The simulator's ~x and ~y follow the same rule (within
  // 1e6 of the origin): Bullet works in single precision, whose step at 1e6 m is 6 cm, so
  // nothing farther can be simulated to the centimetre; 1e300 would silently blind the laser.
  double coordinate(const YAML::Node& node, const std::string& what) const {
    const double value = number(node, what);
    if (std::abs(value) > kMaxMetres) fail("'" + what + "' must be metres within 1e6 of the origin, got " + node.Scalar());
    return value;
  }

  double length(const YAML::Node& node, const std::string& what) const {
    const double value = positive(node, what);
    if (value > kMaxMetres) fail("'" + what + "' must be at most 1e6 metres, got " + node.Scalar());
    return value;
  }

  // A pose [x, y] or [x, y, yaw]: metres within 1e6 of the origin, radians within 1000
  // (the simulator's ~yaw rule).
  Pose2D pose(const YAML::Node& node, const std::string& what) const {
    const auto p = numbers(node, what, 2, 3);
    for (size_t i = 0; i < p.size(); ++i) {
      const double limit = i < 2 ? kMaxMetres : 1e3;
      if (std::abs(p[i]) > limit) {
        fail("'" + what + "' must be metres within 1e6 of the origin and a yaw within 1000 rad");
      }
    }
    return Pose2D{p[0], p[1], p.size() > 2 ? p[2] : 0.0};
  }

  static constexpr double kMaxMetres = 1e6;

 private:
  std::string source_;
};

std::string join_path(const std::string& base_dir, const std::string& path) {
  if (path.empty() || path[0] == '/' || base_dir.empty()) return path;
  return base_dir + "/" + path;
}

std::string dir_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// yaml-cpp keeps every pair of a mapping and answers a lookup with the first, where PyYAML (and
// so world_start.py, world_check.py, map_server) would take the last: refuse the ambiguity,
// naming the key and both lines, as rosbook_env.yaml_files does for the Python readers.
void refuse_duplicate_keys(const YAML::Node& node, const Parser& parser, int depth = 0) {
  if (depth > 64) parser.fail("nested too deeply to be a world file");
  if (node.IsMap()) {
    std::map<std::string, int> first_line;
    for (const auto& pair : node) {
      const int line = pair.first.Mark().line + 1;
      const std::string key = pair.first.IsScalar() ? pair.first.Scalar() : YAML::Dump(pair.first);
      const auto [seen, fresh] = first_line.emplace(key, line);
      if (!fresh) {
        parser.fail("key '" + key + "' given twice (lines " + std::to_string(seen->second) + " and " +
                    std::to_string(line) + "); keep one of them");
      }
      refuse_duplicate_keys(pair.second, parser, depth + 1);
    }
  } else if (node.IsSequence()) {
    for (const auto& item : node) refuse_duplicate_keys(item, parser, depth + 1);
  }
}

}  // namespace

std::vector<std::uint8_t> threshold_occupied(const std::vector<std::uint8_t>& pixels, bool negate,
                                             double occupied_thresh) {
  std::vector<std::uint8_t> occupied(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) {
    const double v = pixels[i];
    const double p = negate ? v / 255.0 : (255.0 - v) / 255.0;
    occupied[i] = p > occupied_thresh ? 1 : 0;
  }
  return occupied;
}

WorldSpec parse_world_yaml(const std::string& text, const std::string& source, const std::string& base_dir) {
  Parser parser(source);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    parser.fail("YAML syntax error at line " + std::to_string(e.mark.line + 1) + ", column " +
                std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
  if (!root.IsMap()) parser.fail("expected a YAML mapping (keys such as image, resolution, origin)");
  refuse_duplicate_keys(root, parser);

  WorldSpec spec;
  spec.source = source;
  if (root["wall_height"]) spec.wall_height = parser.length(root["wall_height"], "wall_height");
  spec.wall_color = parser.color(root["wall_color"], "wall_color", spec.wall_color);
  if (root["start"]) {
    spec.has_start = true;
    spec.start = parser.pose(root["start"], "start");
  }

  if (root["image"]) {
    if (!root["image"].IsScalar() || root["image"].Scalar().empty()) parser.fail("'image' must be a file name");
    for (const char* key : {"resolution", "origin"}) {
      if (!root[key]) parser.fail(std::string("missing key '") + key + "' (required with 'image')");
    }
    GridSpec& grid = spec.grid;
    grid.resolution = parser.length(root["resolution"], "resolution");
    parser.numbers(root["origin"], "origin", 3, 3);  // exactly [x, y, yaw]
    grid.origin = parser.pose(root["origin"], "origin");
    bool negate = false;
    if (const YAML::Node n = root["negate"]) {
      const std::string v = n.IsScalar() ? n.Scalar() : "";
      if (v == "0" || v == "false") negate = false;
      else if (v == "1" || v == "true") negate = true;
      else parser.fail("'negate' must be 0 or 1");
    }
    double occupied_thresh = 0.65;
    if (root["occupied_thresh"]) {
      occupied_thresh = parser.number(root["occupied_thresh"], "occupied_thresh");
      if (occupied_thresh <= 0 || occupied_thresh > 1) parser.fail("'occupied_thresh' must lie in (0, 1]");
    }
    if (root["free_thresh"]) {
      const double free_thresh = parser.number(root["free_thresh"], "free_thresh");
      if (free_thresh < 0 || free_thresh > occupied_thresh) {
        parser.fail("'free_thresh' must lie in [0, occupied_thresh]");
      }
    }
    const std::string image_path = join_path(base_dir, root["image"].Scalar());
    GreyImage image;
    try {
      image = read_pnm(image_path);
    } catch (const ImageError& e) {
      parser.fail("image '" + image_path + "': " + e.what());
    }
    if (std::max(image.width, image.height) * grid.resolution > 2 * Parser::kMaxMetres) {
      parser.fail("the map (" + std::to_string(image.width) + " x " + std::to_string(image.height) +
                  " cells at 'resolution' " + root["resolution"].Scalar() +
                  ") spans more than 2e6 metres: is the resolution in metres per cell?");
    }
    grid.width = image.width;
    grid.height = image.height;
    grid.occupied = threshold_occupied(image.pixels, negate, occupied_thresh);
  }

  if (const auto boxes = root["boxes"]) {
    if (!boxes.IsSequence()) parser.fail("'boxes' must be a list");
    for (size_t i = 0; i < boxes.size(); ++i) {
      const std::string name = "boxes[" + std::to_string(i) + "]";
      const YAML::Node b = boxes[i];
      if (!b.IsMap() || !b["pose"] || !b["size"]) parser.fail(name + " needs 'pose' [x, y, yaw] and 'size' [sx, sy, sz]");
      BoxSpec box;
      box.pose = parser.pose(b["pose"], name + ".pose");
      const auto size = parser.numbers(b["size"], name + ".size", 3, 3);
      for (double s : size) {
        if (s <= 0 || s > Parser::kMaxMetres) parser.fail(name + ".size must be positive metres, at most 1e6");
      }
      box.size_x = size[0];
      box.size_y = size[1];
      box.size_z = size[2];
      box.color = parser.color(b["color"], name + ".color", Color{0.55f, 0.35f, 0.2f});
      spec.boxes.push_back(box);
    }
  }
  if (const auto cylinders = root["cylinders"]) {
    if (!cylinders.IsSequence()) parser.fail("'cylinders' must be a list");
    for (size_t i = 0; i < cylinders.size(); ++i) {
      const std::string name = "cylinders[" + std::to_string(i) + "]";
      const YAML::Node c = cylinders[i];
      if (!c.IsMap() || !c["position"] || !c["radius"] || !c["height"]) {
        parser.fail(name + " needs 'position' [x, y], 'radius' and 'height'");
      }
      CylinderSpec cyl;
      const auto p = parser.numbers(c["position"], name + ".position", 2, 2);
      cyl.x = parser.coordinate(c["position"][0], name + ".position[0]");
      cyl.y = parser.coordinate(c["position"][1], name + ".position[1]");
      cyl.radius = parser.length(c["radius"], name + ".radius");
      cyl.height = parser.length(c["height"], name + ".height");
      cyl.color = parser.color(c["color"], name + ".color", Color{0.2f, 0.45f, 0.7f});
      spec.cylinders.push_back(cyl);
    }
  }
  if (!root["image"] && spec.boxes.empty() && spec.cylinders.empty()) {
    parser.fail("empty world: give an 'image' (map_server map) and/or 'boxes'/'cylinders'");
  }
  return spec;
}

WorldSpec load_world_file(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) {
    throw WorldFileError("world file '" + path + "': is a directory, expected a YAML file");
  }
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
    // /dev/zero would be read until memory runs out, a FIFO would block for ever.
    throw WorldFileError("world file '" + path + "': not a regular file (a device or a pipe), expected a YAML file");
  }
  std::ifstream in(path);
  if (!in) throw WorldFileError("world file '" + path + "': cannot open: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_world_yaml(text.str(), path, dir_name(path));
}

std::string resolve_world_path(const std::string& world, const std::string& worlds_dir) {
  const bool is_path = world.find('/') != std::string::npos ||
                       (world.size() > 5 && world.compare(world.size() - 5, 5, ".yaml") == 0);
  return is_path ? world : worlds_dir + "/" + world + ".yaml";
}

}  // namespace bullet_turtlebot
