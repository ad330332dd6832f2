#include "aco/engine/map_io.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>

#include "aco/error.hpp"
#include "aco/engine/input_file.hpp"
#include "aco/memory_limit.hpp"

namespace aco {
namespace {

// Reads lines and remembers the line number, for messages like "arena.map:7: ...".
class LineReader {
 public:
  LineReader(std::istream& in, std::string name) : in_(in), name_(std::move(name)) {}
  // The next line, as std::getline reads it, but never longer than kMaxLine: a file that is
  // one endless line (binary data, say) is refused before it fills the memory.
  bool next(std::string& line) {
    line.clear();
    std::streambuf& buffer = *in_.rdbuf();
    int c = buffer.sbumpc();
    if (c == std::char_traits<char>::eof()) return false;
    for (; c != std::char_traits<char>::eof() && c != '\n'; c = buffer.sbumpc()) {
      if (line.size() >= kMaxLine)
        fail_at(number_ + 1, "a line longer than " + std::to_string(kMaxLine >> 20) + " MiB: not a map file");
      line.push_back(static_cast<char>(c));
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    ++number_;
    return true;
  }
  static constexpr std::size_t kMaxLine = std::size_t(16) << 20;  // a matrix row of 8 million cells
  [[noreturn]] void fail(const std::string& what) const { fail_at(number_, what); }
  [[noreturn]] void fail_at(int line, const std::string& what) const {
    throw Error(name_ + ":" + std::to_string(line) + ": " + what);
  }
  const std::string& name() const { return name_; }
  int line_number() const { return number_; }

 private:
  std::istream& in_;
  std::string name_;
  int number_ = 0;
};

std::vector<std::string> split_whitespace(const std::string& line) {
  std::istringstream s(line);
  std::vector<std::string> words;
  for (std::string w; s >> w;) words.push_back(w);
  return words;
}

bool is_blank(const std::string& line) { return line.find_first_not_of(" \t") == std::string::npos; }

template <class Number>
bool parse_number(const std::string& text, Number& value) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

int parse_dimension(const LineReader& reader, const std::string& text, const std::string& what) {
  int value = 0;
  if (!parse_number(text, value) || value <= 0 || value > 100000)
    reader.fail(what + " '" + text + "' is not a whole number between 1 and 100000");
  return value;
}

// A finite real number, as the heights and header values of an ESRI grid must be.
double parse_real(const LineReader& reader, const std::string& text, const std::string& what) {
  double value = 0;
  if (!parse_number(text, value) || !std::isfinite(value)) reader.fail(what + " '" + text + "' is not a number");
  return value;
}

// Called with the size a header claims, before anything of that size is allocated. The
// neighbourhood is not known yet: the leanest is checked here, the run's in build_graph().
void check_memory(std::int64_t width, std::int64_t height, const std::string& name) {
  check_planning_memory(width, height, Neighbourhood::four, name);
}

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::ifstream open(const std::filesystem::path& file) {
  check_input_file(file);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": cannot open file");
  return in;
}

// Splits a line at blanks and tabs into at most `max` words, without the stream machinery of
// split_whitespace(): a voxel world has hundreds of thousands of lines. Returns the number of
// words, max + 1 if there are more.
std::size_t split_fields(const std::string& line, std::string_view* words, std::size_t max) {
  std::size_t n = 0;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i == line.size()) break;
    const std::size_t begin = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (n == max) return max + 1;
    words[n++] = std::string_view(line).substr(begin, i - begin);
  }
  return n;
}

template <class Number>
bool parse_number(std::string_view text, Number& value) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

}  // namespace

OccupancyGrid read_movingai_map(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  std::string line;
  int width = 0, height = 0;
  bool typed = false;
  // Header: "type", "height", "width" in any order, ended by "map".
  for (;;) {
    if (!reader.next(line)) reader.fail("truncated header: expected 'type', 'height', 'width' and 'map' lines");
    const auto words = split_whitespace(line);
    if (words.empty()) continue;
    if (words[0] == "map" && words.size() == 1) break;
    if (words.size() != 2)
      reader.fail("bad header line '" + line + "': expected 'type octile', 'height H', 'width W' or 'map'");
    if (words[0] == "type") {
      if (words[1] != "octile") reader.fail("map type '" + words[1] + "' is not supported (expected 'type octile')");
      typed = true;
    } else if (words[0] == "height")
      height = parse_dimension(reader, words[1], "height");
    else if (words[0] == "width")
      width = parse_dimension(reader, words[1], "width");
    else
      reader.fail("bad header line '" + line + "': expected 'type octile', 'height H', 'width W' or 'map'");
  }
  if (!typed || width == 0 || height == 0) reader.fail("header lacks a 'type', 'height' or 'width' line before 'map'");
  check_memory(width, height, name);
  OccupancyGrid grid(width, height, name);
  for (int y = 0; y < height; ++y) {
    if (!reader.next(line))
      reader.fail("truncated map: expected " + std::to_string(height) + " rows, found " + std::to_string(y));
    if (static_cast<int>(line.size()) != width)
      reader.fail("row " + std::to_string(y) + " has " + std::to_string(line.size()) + " characters, expected " +
                  std::to_string(width));
    for (int x = 0; x < width; ++x) {
      switch (line[x]) {
        case '.':
        case 'G':
        case 'S':
          break;
        case '@':
        case 'O':
        case 'T':
        case 'W':
          grid.set_blocked({x, y}, true);
          break;
        default:
          reader.fail("unknown character '" + std::string(1, line[x]) + "' at column " + std::to_string(x) +
                      " (passable: . G S; blocked: @ O T W)");
      }
    }
  }
  while (reader.next(line))
    if (!is_blank(line)) reader.fail("unexpected text after the " + std::to_string(height) + " map rows");
  return grid;
}

OccupancyGrid read_matrix_map(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  std::vector<std::vector<std::uint8_t>> rows;
  std::string line;
  bool ended = false;  // a blank line after rows ends the matrix; only blank lines may follow
  while (reader.next(line)) {
    if (is_blank(line)) {
      ended = !rows.empty();
      continue;
    }
    if (ended) reader.fail("matrix rows continue after a blank line");
    std::vector<std::uint8_t> row;
    for (const auto& word : split_whitespace(line)) {
      int value = 0;
      if (!parse_number(word, value)) reader.fail("'" + word + "' is not a number; expected 0 (free) or 1 (blocked)");
      if (value != 0 && value != 1) reader.fail("value " + word + " is neither 0 (free) nor 1 (blocked)");
      row.push_back(static_cast<std::uint8_t>(value));
    }
    if (!rows.empty() && row.size() != rows.front().size())
      reader.fail("row has " + std::to_string(row.size()) + " values, the first row has " +
                  std::to_string(rows.front().size()));
    check_memory(static_cast<std::int64_t>(row.size()), static_cast<std::int64_t>(rows.size()) + 1, name);
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw Error(name + ": no matrix rows (expected lines of 0/1 values)");
  OccupancyGrid grid(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), name);
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x) grid.set_blocked({x, y}, rows[y][x] != 0);
  return grid;
}

OccupancyGrid load_movingai_map(const std::filesystem::path& file) {
  std::ifstream in = open(file);
  return read_movingai_map(in, file.string());
}

OccupancyGrid load_matrix_map(const std::filesystem::path& file) {
  std::ifstream in = open(file);
  return read_matrix_map(in, file.string());
}

GreyImage load_pgm(const std::filesystem::path& file) {
  std::ifstream in = open(file);
  return read_pgm(in, file.string());
}

GreyImage read_pgm(std::istream& in, const std::string& name) {
  // Header tokens, skipping '#' comments.
  auto token = [&]() {
    std::string t;
    char c;
    while (in.get(c)) {
      if (c == '#') {
        std::string skip;
        std::getline(in, skip);
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        if (!t.empty()) return t;
      } else {
        t += c;
      }
    }
    return t;
  };
  const std::string magic = token();
  if (magic != "P5" && magic != "P2")
    throw Error(name + ": not a PGM image (magic '" + magic + "', expected P5 or P2)");
  GreyImage image;
  const std::string w = token(), h = token(), m = token();
  if (!parse_number(w, image.width) || !parse_number(h, image.height) || !parse_number(m, image.maxval) ||
      image.width <= 0 || image.height <= 0 || image.maxval <= 0 || image.maxval > 65535)
    throw Error(name + ": bad PGM header (width '" + w + "', height '" + h + "', maxval '" + m + "')");
  check_memory(image.width, image.height, name);
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
  image.pixels.resize(count);
  if (magic == "P5") {
    const int bytes = image.maxval > 255 ? 2 : 1;
    std::vector<unsigned char> raw(count * bytes);
    in.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size()));
    if (static_cast<std::size_t>(in.gcount()) != raw.size())
      throw Error(name + ": truncated PGM data (" + std::to_string(in.gcount()) + " of " + std::to_string(raw.size()) +
                  " bytes)");
    for (std::size_t i = 0; i < count; ++i)
      image.pixels[i] = bytes == 1 ? raw[i] : (raw[2 * i] << 8) | raw[2 * i + 1];  // 16-bit PGM is big-endian
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      const std::string t = token();
      if (t.empty())
        throw Error(name + ": truncated PGM data (" + std::to_string(i) + " of " + std::to_string(count) + " values)");
      if (!parse_number(t, image.pixels[i])) throw Error(name + ": PGM value '" + t + "' is not a number");
    }
  }
  for (int v : image.pixels)
    if (v < 0 || v > image.maxval) throw Error(name + ": PGM value " + std::to_string(v) + " exceeds maxval");
  return image;
}

OccupancyGrid load_ros_map(const std::filesystem::path& yaml_file) {
  const std::string name = yaml_file.string();
  check_input_file(yaml_file);
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(name);
  } catch (const YAML::BadFile&) {
    throw Error(name + ": cannot open file");
  } catch (const YAML::Exception& e) {
    throw Error(name + ":" + std::to_string(e.mark.line + 1) + ": invalid YAML: " + e.msg);
  }
  if (!doc.IsMap()) throw Error(name + ": expected a YAML mapping with keys image, resolution, origin, ...");
  auto get = [&](const char* key, auto fallback, bool required) {
    using T = decltype(fallback);
    const YAML::Node node = doc[key];
    if (!node) {
      if (required) throw Error(name + ": missing key '" + key + "'");
      return fallback;
    }
    try {
      return node.as<T>();
    } catch (const YAML::Exception&) {
      throw Error(name + ":" + std::to_string(node.Mark().line + 1) + ": key '" + key +
                  "' has a value of the wrong type");
    }
  };
  const auto image_name = get("image", std::string(), true);
  const double resolution = get("resolution", 0.0, true);
  const auto origin = get("origin", std::vector<double>(), true);
  const int negate = get("negate", 0, false);
  const double occupied = get("occupied_thresh", 0.65, false);
  const double free = get("free_thresh", 0.196, false);
  const auto mode = get("mode", std::string("trinary"), false);
  if (!(resolution > 0)) throw Error(name + ": resolution must be positive");
  if (origin.size() != 3) throw Error(name + ": origin must be a list of three numbers [x, y, yaw]");
  if (negate != 0 && negate != 1) throw Error(name + ": negate must be 0 or 1");
  if (!(free >= 0 && free <= occupied && occupied <= 1))
    throw Error(name + ": thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
  if (mode != "trinary" && mode != "scale" && mode != "raw")
    throw Error(name + ": mode '" + mode + "' is not one of trinary, scale, raw");

  std::filesystem::path image_file = image_name;
  if (image_file.is_relative()) image_file = yaml_file.parent_path() / image_file;
  if (image_file.extension() != ".pgm")
    throw Error(name + ": image '" + image_name + "' is not a .pgm file (only PGM images are supported)");
  const GreyImage image = load_pgm(image_file);
  OccupancyGrid grid(image.width, image.height, name);
  grid.set_geometry({resolution, {origin[0], origin[1], origin[2]}});
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const int v = image.pixels[static_cast<std::size_t>(y) * image.width + x];
      // map_server: p = occupancy probability; cells between the thresholds are unknown,
      // and a planner must not drive through unknown space. In raw mode map_server takes the
      // value as an occupancy percentage and ignores negate; a planner still has to decide
      // free or not, so the free threshold applies to it too (values above 100 are unknown).
      const double p = mode == "raw" ? v / 100.0
                       : negate      ? double(v) / image.maxval
                                     : double(image.maxval - v) / image.maxval;
      grid.set_blocked({x, y}, !(p < free));
    }
  }
  return grid;
}

TerrainMap read_esri_ascii(std::istream& in, const std::string& name, const TerrainOptions& options) {
  LineReader reader(in, name);
  static const char* const kKeys =
      "ncols, nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize, NODATA_value";
  // Header: "KEY VALUE" lines until the first line that starts like a number.
  std::map<std::string, double> header;  // lower-case key -> value
  std::string line;
  bool data_started = false;
  while (reader.next(line)) {
    const auto words = split_whitespace(line);
    if (words.empty()) continue;
    const char first = words[0].front();
    if (std::isdigit(static_cast<unsigned char>(first)) || first == '-' || first == '+' || first == '.') {
      data_started = true;
      break;
    }
    const std::string key = lower_case(words[0]);
    static const std::vector<std::string> known = {"ncols",     "nrows",     "xllcorner", "xllcenter",
                                                   "yllcorner", "yllcenter", "cellsize",  "nodata_value"};
    if (std::find(known.begin(), known.end(), key) == known.end())
      reader.fail("unknown header key '" + words[0] + "' (expected " + kKeys + ")");
    if (words.size() != 2) reader.fail("header line '" + line + "' should be '" + words[0] + " VALUE'");
    const double value = key == "ncols" || key == "nrows" ? parse_dimension(reader, words[1], words[0])
                                                          : parse_real(reader, words[1], words[0]);
    if (key == "cellsize" && !(value > 0)) reader.fail("cellsize '" + words[1] + "' is not positive");
    if (!header.emplace(key, value).second) reader.fail("header key '" + words[0] + "' is given twice");
  }
  for (const char* key : {"ncols", "nrows", "cellsize"})
    if (!header.count(key))
      reader.fail(std::string("header lacks '") + key + "' (an ESRI ASCII grid needs " + kKeys + ")");
  for (const char* axis : {"x", "y"}) {
    const std::string corner = std::string(axis) + "llcorner", centre = std::string(axis) + "llcenter";
    if (header.count(corner) == header.count(centre))
      reader.fail("header needs exactly one of '" + corner + "' and '" + centre + "'");
  }
  if (!data_started) reader.fail("no heights after the header");
  const int ncols = static_cast<int>(header["ncols"]);
  const int nrows = static_cast<int>(header["nrows"]);
  const double cell_size = header["cellsize"];
  const double nodata = header.count("nodata_value") ? header["nodata_value"] : -9999.0;
  auto lower_left = [&](const std::string& axis) {
    return header.count(axis + "llcorner") ? header[axis + "llcorner"] : header[axis + "llcenter"] - cell_size / 2;
  };
  const Eigen::Vector2d corner(lower_left("x"), lower_left("y"));
  check_memory(ncols, nrows, name);

  const std::size_t expected = static_cast<std::size_t>(ncols) * nrows;
  std::vector<double> heights;
  std::size_t found = 0;
  int first_extra_line = 0;
  do {
    for (const auto& word : split_whitespace(line)) {
      const double h = parse_real(reader, word, "height");
      if (++found > expected) {
        if (first_extra_line == 0) first_extra_line = reader.line_number();
        continue;
      }
      heights.push_back(h == nodata ? std::numeric_limits<double>::quiet_NaN() : h);
    }
  } while (reader.next(line));
  if (found != expected)
    reader.fail_at(found > expected ? first_extra_line : reader.line_number(),
                   "expected " + std::to_string(expected) + " heights (nrows " + std::to_string(nrows) + " x ncols " +
                       std::to_string(ncols) + "), found " + std::to_string(found));
  TerrainMap map(ncols, nrows, cell_size, std::move(heights), options.max_slope_deg, name);
  map.set_lower_left(corner);
  return map;
}

TerrainMap load_esri_ascii(const std::filesystem::path& file, const TerrainOptions& options) {
  std::ifstream in = open(file);
  return read_esri_ascii(in, file.string(), options);
}

TerrainMap read_height_pgm(std::istream& in, const std::string& name, const TerrainOptions& options) {
  if (!(options.height_scale > 0) || !std::isfinite(options.height_scale))
    throw Error(name + ": height scale " + std::to_string(options.height_scale) + " is not a positive number");
  const GreyImage image = read_pgm(in, name);
  std::vector<double> heights(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), heights.begin(),
                 [&](int grey) { return grey * options.height_scale; });
  return TerrainMap(image.width, image.height, options.cell_size, std::move(heights), options.max_slope_deg, name);
}

TerrainMap load_height_pgm(const std::filesystem::path& file, const TerrainOptions& options) {
  std::ifstream in = open(file);
  return read_height_pgm(in, file.string(), options);
}

VoxelMap read_movingai_voxels(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  std::string line;
  std::string_view f[4];
  if (!reader.next(line)) reader.fail_at(1, "empty voxel file (expected a first line 'voxel WIDTH HEIGHT DEPTH')");
  if (split_fields(line, f, 4) != 4 || f[0] != "voxel")
    reader.fail("expected a first line 'voxel WIDTH HEIGHT DEPTH', found '" + line + "'");
  const int width = parse_dimension(reader, std::string(f[1]), "width");
  const int height = parse_dimension(reader, std::string(f[2]), "height");
  const int depth = parse_dimension(reader, std::string(f[3]), "depth");
  check_voxel_world_memory(width, height, depth, name);  // its edges: when its graph is built
  VoxelMap map(width, height, depth, name);
  const int size[3] = {width, height, depth};
  static const char* const kAxis[3] = {"x", "y", "z"};
  while (reader.next(line)) {
    const std::size_t n = split_fields(line, f, 3);
    if (n == 0) continue;
    if (n != 3)
      reader.fail("expected a blocked voxel 'x y z', found " + std::string(n > 3 ? "more than 3" : std::to_string(n)) +
                  " field" + (n == 1 ? "" : "s") + " in '" + line + "'");
    int c[3];
    for (int i = 0; i < 3; ++i) {
      if (!parse_number(f[i], c[i]))
        reader.fail(std::string(kAxis[i]) + " '" + std::string(f[i]) + "' is not a whole number");
      if (c[i] < 0 || c[i] >= size[i])
        reader.fail("voxel (" + std::string(f[0]) + "," + std::string(f[1]) + "," + std::string(f[2]) +
                    ") is outside the " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                    std::to_string(depth) + " world (" + kAxis[i] + " must be 0 to " + std::to_string(size[i] - 1) +
                    ")");
    }
    map.set_blocked({c[0], c[1], c[2]}, true);
  }
  return map;
}

VoxelMap load_movingai_voxels(const std::filesystem::path& file) {
  std::ifstream in = open(file);
  return read_movingai_voxels(in, file.string());
}

void write_movingai_voxels(const VoxelMap& map, std::ostream& out) {
  std::string text = "voxel " + std::to_string(map.width()) + " " + std::to_string(map.height()) + " " +
                     std::to_string(map.depth()) + "\n";
  char buffer[48];
  for (int x = 0; x < map.width(); ++x)
    for (int y = 0; y < map.height(); ++y)
      for (int z = 0; z < map.depth(); ++z) {
        if (!map.blocked({x, y, z})) continue;
        char* p = buffer;
        for (const int v : {x, y, z}) {
          if (p != buffer) *p++ = ' ';
          p = std::to_chars(p, buffer + sizeof buffer, v).ptr;
        }
        *p++ = '\n';
        text.append(buffer, p);
      }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

std::vector<Scenario> read_scenarios(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  std::string line;
  if (!reader.next(line)) reader.fail("empty scenario file (expected 'version 1')");
  const auto head = split_whitespace(line);
  if (head.size() != 2 || head[0] != "version" || (head[1] != "1" && head[1] != "1.0"))
    reader.fail("expected 'version 1', found '" + line + "'");
  std::vector<Scenario> scenarios;
  while (reader.next(line)) {
    if (is_blank(line)) continue;
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string w; std::getline(fields, w, '\t');) f.push_back(w);
    if (f.size() != 9) f = split_whitespace(line);
    if (f.size() != 9)
      reader.fail(
          "expected 9 fields (bucket, map, width, height, start x, start y, goal x, goal y, optimal length), found " +
          std::to_string(f.size()));
    Scenario s;
    s.map_path = f[1];
    const bool ok = parse_number(f[0], s.bucket) && parse_number(f[2], s.width) && parse_number(f[3], s.height) &&
                    parse_number(f[4], s.start.x) && parse_number(f[5], s.start.y) && parse_number(f[6], s.goal.x) &&
                    parse_number(f[7], s.goal.y) && parse_number(f[8], s.optimal_length);
    if (!ok || s.width <= 0 || s.height <= 0 || s.optimal_length < 0)
      reader.fail("malformed scenario line '" + line + "'");
    scenarios.push_back(s);
  }
  return scenarios;
}

std::vector<Scenario> load_scenarios(const std::filesystem::path& file) {
  if (file.extension() == ".3dscen") return load_voxel_scenarios(file);
  std::ifstream in = open(file);
  return read_scenarios(in, file.string());
}

std::vector<Scenario> read_voxel_scenarios(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  std::string line;
  std::string_view f[8];
  if (!reader.next(line)) reader.fail_at(1, "empty scenario file (expected 'version 1')");
  if (split_fields(line, f, 2) != 2 || f[0] != "version" || (f[1] != "1" && f[1] != "1.0"))
    reader.fail("expected 'version 1', found '" + line + "'");
  if (!reader.next(line) || split_fields(line, f, 1) != 1)
    reader.fail_at(2, "expected the map's file name on line 2 (e.g. 'Simple.3dmap')");
  const std::string map_path(f[0]);
  std::vector<Scenario> scenarios;
  while (reader.next(line)) {
    const std::size_t n = split_fields(line, f, 8);
    if (n == 0) continue;
    if (n != 7 && n != 8)
      reader.fail("expected 8 fields (start x y z, goal x y z, optimal length, ratio), or 7 without the ratio, found " +
                  std::string(n > 8 ? "more than 8" : std::to_string(n)));
    Scenario s;
    s.map_path = map_path;
    s.volumetric = true;
    int c[6];
    for (int i = 0; i < 6; ++i)
      if (!parse_number(f[i], c[i]) || c[i] < 0)
        reader.fail(std::string(i < 3 ? "start " : "goal ") + "xyz"[i % 3] + " '" + std::string(f[i]) +
                    "' is not a whole number of at least 0");
    s.start = {c[0], c[1], c[2]};
    s.goal = {c[3], c[4], c[5]};
    if (!parse_number(f[6], s.optimal_length) || !std::isfinite(s.optimal_length) || s.optimal_length < 0)
      reader.fail("optimal length '" + std::string(f[6]) + "' is not a number of at least 0");
    if (n == 8 && (!parse_number(f[7], s.ratio) || !std::isfinite(s.ratio) || s.ratio < 0))
      reader.fail("ratio '" + std::string(f[7]) + "' is not a number of at least 0");
    scenarios.push_back(s);
  }
  return scenarios;
}

std::vector<Scenario> load_voxel_scenarios(const std::filesystem::path& file) {
  std::ifstream in = open(file);
  return read_voxel_scenarios(in, file.string());
}

std::filesystem::path scenario_map_file(const std::filesystem::path& scen_file) {
  if (scen_file.extension() != ".scen" && scen_file.extension() != ".3dscen")
    throw Error(scen_file.string() +
                ": a scenario file name must end in .scen (e.g. arena.map.scen) or .3dscen (e.g. Simple.3dmap.3dscen)");
  std::filesystem::path map = scen_file;
  map.replace_extension();
  return map;
}

}  // namespace aco
