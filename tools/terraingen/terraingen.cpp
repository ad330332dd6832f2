// aco_terraingen: reproducible synthetic terrain as ESRI ASCII grids (.asc) or PGM height
// images (.pgm, 8 or 16 bit), a sum of seeded Gaussian hills on a base height.
//
//   aco_terraingen --width 64 --height 48 --seed 3 --hills 20 --out my.asc
//   aco_terraingen --relief 25 --base 0 --height-scale 0.1 --bits 8 --out hill.pgm   # grey = height / 0.1
//   aco_terraingen --paper000 data/terrain     # the look-alikes of paper 000's maps, with .scen
//
// Deterministic: aco::Rng only (no std:: distributions, no clock) and heights written with two
// decimals, so two runs write byte-identical files.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/parameters.hpp"
#include "aco/rng.hpp"

namespace {

constexpr aco::ParamSpec kOptions[] = {
    {"width", aco::ParamType::integer, "20", "1:100000", "columns"},
    {"height", aco::ParamType::integer, "20", "1:100000", "rows"},
    {"seed", aco::ParamType::integer, "1", "0:1000000000000", "random seed of the hills"},
    {"hills", aco::ParamType::integer, "6", "0:100000", "number of random hills"},
    {"hill-radius", aco::ParamType::real, "3", "(0:1e6]",
     "mean standard deviation of a hill, in cells (each hill draws from [0.5, 1.5] times it)"},
    {"base", aco::ParamType::real, "800", "-1e6:1e6", "height of the plain between the hills"},
    {"relief", aco::ParamType::real, "200", "0:1e6", "height of the highest point above the base"},
    {"cellsize", aco::ParamType::real, "10", "(0:1e6]", "horizontal size of a cell, in the heights' units (.asc)"},
    {"height-scale", aco::ParamType::real, "1", "(0:1e12]",
     ".pgm: height per grey level, grey = height / X rounded (plan with acoplan --height-scale X)"},
    {"bits", aco::ParamType::integer, "16", "8:8:16", ".pgm: grey levels of 8 or 16 bits"},
};

struct Hill {
  double x, y;  // centre, in cells
  double sigma;  // standard deviation, in cells
  double amplitude;  // relative; the whole relief is scaled so the highest point is base + relief
};

struct TerrainSpec {
  int width = 20;
  int height = 20;
  std::uint64_t seed = 1;
  int hills = 6;
  double hill_radius = 3;
  double base = 800;
  double relief = 200;
  double cellsize = 10;
  double height_scale = 1;
  int bits = 16;
  std::vector<Hill> extra_hills;  // placed by hand, besides the random ones
};

TerrainSpec spec_from(const aco::ParameterValues& v) {
  TerrainSpec s;
  s.width = static_cast<int>(v.integer("width"));
  s.height = static_cast<int>(v.integer("height"));
  s.seed = static_cast<std::uint64_t>(v.integer("seed"));
  s.hills = static_cast<int>(v.integer("hills"));
  s.hill_radius = v.real("hill-radius");
  s.base = v.real("base");
  s.relief = v.real("relief");
  s.cellsize = v.real("cellsize");
  s.height_scale = v.real("height-scale");
  s.bits = static_cast<int>(v.integer("bits"));
  return s;
}

// Heights, row-major, row 0 at the top.
std::vector<double> generate(const TerrainSpec& s) {
  aco::Rng rng(s.seed);
  std::vector<Hill> hills = s.extra_hills;
  for (int i = 0; i < s.hills; ++i) {
    Hill h{};
    h.x = rng.uniform(0, s.width);
    h.y = rng.uniform(0, s.height);
    h.sigma = s.hill_radius * rng.uniform(0.5, 1.5);
    h.amplitude = rng.uniform(0.3, 1.0);
    hills.push_back(h);
  }
  std::vector<double> bumps(static_cast<std::size_t>(s.width) * s.height, 0.0);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      for (const Hill& h : hills) {
        const double d2 = (x - h.x) * (x - h.x) + (y - h.y) * (y - h.y);
        bumps[static_cast<std::size_t>(y) * s.width + x] += h.amplitude * std::exp(-d2 / (2 * h.sigma * h.sigma));
      }
  const double top = *std::max_element(bumps.begin(), bumps.end());
  std::vector<double> heights(bumps.size());
  for (std::size_t i = 0; i < bumps.size(); ++i) heights[i] = s.base + (top > 0 ? s.relief * bumps[i] / top : 0.0);
  return heights;
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string esri_ascii(const TerrainSpec& s, const std::vector<double>& heights) {
  std::ostringstream out;
  out << "ncols " << s.width << "\nnrows " << s.height << "\nxllcorner 0\nyllcorner 0\ncellsize "
      << format("%g", s.cellsize) << "\nNODATA_value -9999\n";
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x)
      out << (x ? " " : "") << format("%.2f", heights[static_cast<std::size_t>(y) * s.width + x]);
    out << "\n";
  }
  return out.str();
}

// A binary PGM (P5; 16 bit big-endian, as the format says) of grey = height / height_scale.
std::string height_pgm(const TerrainSpec& s, const std::vector<double>& heights) {
  const int maxval = s.bits == 8 ? 255 : 65535;
  std::string pgm =
      "P5\n" + std::to_string(s.width) + " " + std::to_string(s.height) + "\n" + std::to_string(maxval) + "\n";
  for (std::size_t i = 0; i < heights.size(); ++i) {
    const double grey = std::round(heights[i] / s.height_scale);
    if (grey < 0 || grey > maxval)
      throw aco::Error("height " + format("%g", heights[i]) + " of cell (" + std::to_string(i % s.width) + "," +
                       std::to_string(i / s.width) + ") is grey level " + format("%.0f", grey) + ", outside 0.." +
                       std::to_string(maxval) + " of a " + std::to_string(s.bits) +
                       "-bit PGM: change --base, --relief or --height-scale");
    const auto level = static_cast<unsigned>(grey);
    if (s.bits == 16) pgm += static_cast<char>(level >> 8);
    pgm += static_cast<char>(level & 0xff);
  }
  return pgm;
}

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw aco::Error(file.string() + ": cannot open for writing");
  out << text;
  if (!out.flush()) throw aco::Error(file.string() + ": write failed");
}

// One look-alike of paper 000's maps: start at the left edge at mid-height, goal at the right
// edge a little higher up the map (the paper: (1,10) -> (21,8) on 20x20) and on a hill (the
// paper's goal is 200 above its start).
struct PaperMap {
  std::string name;
  int size;
  std::uint64_t seed;
  int hills;
};

void write_paper000(const PaperMap& m, const std::filesystem::path& dir) {
  TerrainSpec s;
  s.width = s.height = m.size;
  s.seed = m.seed;
  s.hills = m.hills;
  const aco::Cell start{0, m.size / 2};
  const aco::Cell goal{m.size - 1, (2 * m.size) / 5};
  s.extra_hills.push_back({double(goal.x), double(goal.y), 0.2 * m.size, 1.0});
  const std::string text = esri_ascii(s, generate(s));
  // The optimum is computed on the map as acoplan will read it, rounded heights included.
  std::istringstream in(text);
  const aco::TerrainMap map = aco::read_esri_ascii(in, m.name, {});
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  const auto best = aco::astar(graph, graph.node(start), graph.node(goal));
  if (!best) throw aco::Error(m.name + ": goal not reachable");
  const std::string scen = "version 1\n0\t" + m.name + "\t" + std::to_string(m.size) + "\t" + std::to_string(m.size) +
                           "\t" + std::to_string(start.x) + "\t" + std::to_string(start.y) + "\t" +
                           std::to_string(goal.x) + "\t" + std::to_string(goal.y) + "\t" +
                           format("%.8g", best->length) + "\n";
  write_file(dir / m.name, text);
  write_file(dir / (m.name + ".scen"), scen);
  // What the hills cost: a shortest route of the same grid without heights, walked on the terrain.
  const aco::OccupancyGrid flat(m.size, m.size, "flat");
  const aco::Graph flat_graph = aco::build_graph(flat, {aco::Neighbourhood::eight, false});
  const auto flat_best = aco::astar(flat_graph, flat_graph.node(start), flat_graph.node(goal));
  std::cout << m.name << ": " << m.size << "x" << m.size << ", seed " << m.seed << ", " << m.hills
            << " random hills + one on the goal; start " << aco::to_string(start) << " at "
            << format("%.2f", map.elevation(start)) << ", goal " << aco::to_string(goal) << " at "
            << format("%.2f", map.elevation(goal)) << "\n  optimal length " << format("%.8g", best->length)
            << "; without the hills " << format("%.8g", flat_best->length * s.cellsize)
            << "; that flat-optimal route walked over the hills "
            << format("%.8g", aco::path_length(graph, flat_best->nodes)) << "\n";
}

constexpr const char* kUsage =
    "usage: aco_terraingen [--width N --height N --seed N --hills N --hill-radius R --base Z --relief Z --cellsize C] "
    "[--height-scale X --bits 8|16] --out FILE.asc|FILE.pgm\n"
    "       aco_terraingen --paper000 DIR   (writes epf20.asc, epf30.asc, epf50.asc and their .scen into DIR)\n";

}  // namespace

int main(int argc, char** argv) {
  try {
    std::map<std::string, std::string> given;
    std::string out, paper_dir;
    for (int i = 1; i < argc; i += 2) {
      const std::string key = argv[i];
      if (key.rfind("--", 0) != 0 || i + 1 >= argc) throw aco::Error(std::string("expected --OPTION VALUE\n") + kUsage);
      const std::string value = argv[i + 1];
      if (key == "--out")
        out = value;
      else if (key == "--paper000")
        paper_dir = value;
      else
        given[key.substr(2)] = value;
    }
    if (!paper_dir.empty()) {
      if (!given.empty() || !out.empty()) throw aco::Error("--paper000 takes no other option");
      std::filesystem::create_directories(paper_dir);
      // About one hill of radius 3 per 65 cells on each map, so the three look alike up close.
      for (const PaperMap& m :
           {PaperMap{"epf20.asc", 20, 20, 6}, PaperMap{"epf30.asc", 30, 30, 14}, PaperMap{"epf50.asc", 50, 50, 38}})
        write_paper000(m, paper_dir);
      return 0;
    }
    const std::string ending = std::filesystem::path(out).extension().string();
    if (ending != ".asc" && ending != ".pgm")
      throw aco::Error("--out FILE.asc or FILE.pgm is required (the ending chooses the format)\n" +
                       std::string(kUsage));
    const TerrainSpec spec = spec_from(aco::resolve(kOptions, given, "--"));
    write_file(out, ending == ".asc" ? esri_ascii(spec, generate(spec)) : height_pgm(spec, generate(spec)));
  } catch (const std::exception& e) {
    std::cerr << "aco_terraingen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
