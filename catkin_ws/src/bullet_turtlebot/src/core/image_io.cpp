#include "bullet_turtlebot/image_io.hpp"

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace bullet_turtlebot {
namespace {

// Next header token, skipping whitespace and '#' comments.
std::string header_token(std::istream& in) {
  std::string token;
  int c;
  while ((c = in.get()) != EOF) {
    if (c == '#') {
      while ((c = in.get()) != EOF && c != '\n') {
      }
      continue;
    }
    if (std::isspace(c)) {
      if (!token.empty()) return token;
      continue;
    }
    token.push_back(static_cast<char>(c));
  }
  return token;
}

int header_int(std::istream& in, const char* what) {
  const std::string token = header_token(in);
  try {
    size_t used = 0;
    const int value = std::stoi(token, &used);
    if (used == token.size() && value > 0) return value;
  } catch (const std::exception&) {
  }
  throw ImageError(std::string("bad ") + what + " in the image header: '" + token + "'");
}

}  // namespace

GreyImage read_pnm(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
    throw ImageError(S_ISDIR(info.st_mode) ? "is a directory, expected an image"
                                           : "not a regular file (a device or a pipe), expected an image");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImageError(std::string("cannot open: ") + std::strerror(errno));
  const std::string magic = header_token(in);
  if (magic != "P2" && magic != "P5" && magic != "P3" && magic != "P6") {
    throw ImageError("not a PGM/PPM image (magic '" + magic.substr(0, 8) +
                     "'; supported: P2, P5, P3, P6)");
  }
  const bool binary = magic == "P5" || magic == "P6";
  const int channels = (magic == "P3" || magic == "P6") ? 3 : 1;
  GreyImage image;
  image.width = header_int(in, "width");
  image.height = header_int(in, "height");
  const int maxval = header_int(in, "maxval");
  if (maxval > 65535) throw ImageError("maxval above 65535");
  if (static_cast<long long>(image.width) * image.height > 400LL * 1000 * 1000) {
    throw ImageError("image too large");
  }
  const size_t count = static_cast<size_t>(image.width) * image.height;
  const int bytes = maxval > 255 ? 2 : 1;
  // Check the header's size against the bytes the file holds before allocating for it: a
  // 20-byte file declaring 20000 x 20000 16-bit colour pixels must not ask for 2.4 GB.
  // Plain (ASCII) values take at least two bytes each (a digit and a separator).
  const std::streamoff here = in.tellg();
  const auto left = static_cast<unsigned long long>(info.st_size > here ? info.st_size - here : 0);
  const unsigned long long needed = static_cast<unsigned long long>(count) * channels * (binary ? bytes : 2) -
                                    (binary ? 0 : 1);
  if (left < needed) {
    throw ImageError("truncated pixel data (" + std::to_string(left) + " bytes left for a " +
                     std::to_string(image.width) + " x " + std::to_string(image.height) + " image, which needs " +
                     std::to_string(needed) + ")");
  }
  image.pixels.resize(count);
  std::vector<unsigned char> raw;
  if (binary) {
    raw.resize(count * channels * bytes);
    in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size()));
    if (static_cast<size_t>(in.gcount()) != raw.size()) {
      throw ImageError("truncated pixel data (" + std::to_string(in.gcount()) + " of " +
                       std::to_string(raw.size()) + " bytes)");
    }
  }
  for (size_t i = 0; i < count; ++i) {
    long sum = 0;
    for (int c = 0; c < channels; ++c) {
      long v;
      if (binary) {
        const size_t k = (i * channels + c) * bytes;
        v = bytes == 2 ? (raw[k] << 8) | raw[k + 1] : raw[k];
      } else if (!(in >> v)) {
        throw ImageError("truncated pixel data");
      }
      if (v < 0 || v > maxval) throw ImageError("pixel value out of range");
      sum += v;
    }
    const double mean = static_cast<double>(sum) / channels;
    image.pixels[i] = static_cast<std::uint8_t>(mean * 255.0 / maxval + 0.5);
  }
  return image;
}

}  // namespace bullet_turtlebot
