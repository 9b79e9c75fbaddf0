#include "rosbook_env/map_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>

namespace rosbook_env {
namespace {

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string name_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string cannot_write(const std::string& path, int error) {
  if (error == ENOENT) {
    const std::string folder = folder_of(path);
    return "cannot write " + path + ": folder " + folder +
           " does not exist (create it with: mkdir -p '" + folder + "')";
  }
  return "cannot write " + path + ": " + std::strerror(error);
}

// The whole of `bytes` to a new temporary file beside `path`, on disk; returns its name.
// The name keeps at most 64 characters of the target's, so a long name that fits in the
// folder does not make a temporary name that does not.
std::string write_temporary(const std::string& path, const std::string& bytes) {
  std::string pattern = folder_of(path) + "/." + name_of(path).substr(0, 64) + ".XXXXXX";
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) throw MapFileError(cannot_write(path, errno));
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  int error = 0;
  while (left > 0 && error == 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno != EINTR) error = errno;
    if (n > 0) data += n, left -= static_cast<std::size_t>(n);
  }
  // mkstemp makes the file 0600; map_saver's files are 0644 (as atomic.py sets them).
  if (error == 0 && ::fchmod(fd, 0644) != 0) error = errno;
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(pattern.c_str());
    throw MapFileError(cannot_write(path, error));
  }
  return pattern;
}

// The renames are durable only once the folders' entries are on disk; best effort.
void sync_folder(const std::string& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// Whether `name` reads back from "image: NAME" as itself when written plain (the test
// map_saver makes with yaml.safe_load; this one is stricter, and quoting is always right).
bool plain_yaml_scalar(const std::string& name) {
  if (name.empty() || name.front() == ' ' || name.back() == ' ' || name.back() == ':') return false;
  if (std::strchr("-?:,[]{}#&*!|>'\"%@`", name.front()) != nullptr) return false;
  if (name.find(": ") != std::string::npos || name.find(" #") != std::string::npos) return false;
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) return false;
  }
  return true;
}

std::string double_quoted(const std::string& name) {
  std::string out = "\"";
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof(escape), "\\u%04x", u);
      out += escape;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

void check_map(const MapImage& map) {
  if (map.width <= 0 || map.height <= 0) {
    throw MapFileError("cannot save an empty map (" + std::to_string(map.width) + " x " +
                       std::to_string(map.height) + " pixels)");
  }
  if (map.pixels.size() != static_cast<std::size_t>(map.width) * map.height) {
    throw MapFileError("map has " + std::to_string(map.pixels.size()) + " pixels for " +
                       std::to_string(map.width) + " x " + std::to_string(map.height));
  }
  if (!(map.resolution > 0) || !std::isfinite(map.resolution)) {
    throw MapFileError("cannot save a map with resolution " + std::to_string(map.resolution));
  }
  if (!std::isfinite(map.origin_x) || !std::isfinite(map.origin_y) ||
      !std::isfinite(map.origin_yaw)) {
    throw MapFileError("cannot save a map whose origin is not finite");
  }
}

}  // namespace

std::vector<std::uint8_t> pixels_from_occupancy(const std::vector<std::int8_t>& cells, int width,
                                                int height, int occupied, int free) {
  if (width <= 0 || height <= 0 || cells.size() != static_cast<std::size_t>(width) * height) {
    throw MapFileError("occupancy grid has " + std::to_string(cells.size()) + " cells for " +
                       std::to_string(width) + " x " + std::to_string(height));
  }
  if (occupied < 1 || occupied > 100 || free < 0 || free >= occupied) {
    throw MapFileError("thresholds must be 0 <= free < occupied <= 100, got free " +
                       std::to_string(free) + ", occupied " + std::to_string(occupied));
  }
  std::vector<std::uint8_t> pixels(cells.size());
  for (int j = 0; j < height; ++j) {
    const std::size_t row = static_cast<std::size_t>(height - 1 - j) * width;  // top row first
    for (int i = 0; i < width; ++i) {
      const int v = cells[static_cast<std::size_t>(j) * width + i];
      pixels[row + i] = v >= occupied ? kPgmOccupied : (v >= 0 && v <= free ? kPgmFree : kPgmUnknown);
    }
  }
  return pixels;
}

std::string encode_pgm(const MapImage& map, const std::string& comment) {
  std::string header = "P5\n";
  if (!comment.empty()) {
    std::string line = comment;
    for (char& c : line) c = c == '\n' ? ' ' : c;
    header += "# " + line + "\n";
  }
  header += std::to_string(map.width) + " " + std::to_string(map.height) + "\n255\n";
  return header + std::string(map.pixels.begin(), map.pixels.end());
}

std::string map_yaml_text(const std::string& image_name, const MapImage& map) {
  const std::string name = plain_yaml_scalar(image_name) ? image_name : double_quoted(image_name);
  char numbers[256];
  // "+ 0.0": no "-0.000000" (as map_saver writes it).
  std::snprintf(numbers, sizeof(numbers), "resolution: %f\norigin: [%f, %f, %f]\n",
                map.resolution + 0.0, map.origin_x + 0.0, map.origin_y + 0.0,
                map.origin_yaw + 0.0);
  return "image: " + name + "\n" + numbers +
         "negate: 0\n"
         "occupied_thresh: 0.65\n"
         "free_thresh: 0.196\n\n";
}

std::pair<std::string, std::string> write_map_files(const std::string& base, const MapImage& map,
                                                    const std::string& pgm_comment) {
  if (base.empty() || base.back() == '/') {
    throw MapFileError("map base name '" + base + "' has no file name (e.g. " + base +
                       "map writes " + base + "map.pgm and " + base + "map.yaml)");
  }
  check_map(map);
  const std::string pgm = base + ".pgm", yaml = base + ".yaml";
  for (const std::string& path : {pgm, yaml}) {
    struct stat st {};
    // A folder in the way would fail only at its rename, after the image was replaced.
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
      throw MapFileError("cannot write " + path + ": it is a folder");
    }
  }
  write_files_atomically(
      {{pgm, encode_pgm(map, pgm_comment)}, {yaml, map_yaml_text(name_of(pgm), map)}});
  return {pgm, yaml};
}

void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::pair<std::string, std::string>> staged;  // (temporary, target)
  try {
    for (const auto& [path, bytes] : files) staged.emplace_back(write_temporary(path, bytes), path);
    for (const auto& [temporary, path] : staged) {
      if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int error = errno;
        throw MapFileError("cannot rename " + temporary + " to " + path + ": " +
                           std::strerror(error));
      }
    }
  } catch (...) {
    for (const auto& staged_file : staged) ::unlink(staged_file.first.c_str());  // renamed: gone
    throw;
  }
  std::set<std::string> folders;
  for (const auto& staged_file : staged) folders.insert(folder_of(staged_file.second));
  for (const std::string& folder : folders) sync_folder(folder);
}

}  // namespace rosbook_env
