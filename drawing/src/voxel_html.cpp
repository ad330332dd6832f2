#include "aco/drawing/voxel_html.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <tuple>

#include "aco/error.hpp"
#include "aco/process/output_file.hpp"
#include "aco/drawing/svg.hpp"
#include "embedded_text.hpp"
#include "voxel_colours.hpp"

namespace aco {
namespace {

namespace colours = voxel_colours;

// A JSON string; '<' as \u003c so that no "</script>" can end the page's data early.
std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20 || c == '<') {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// Numbers as JSON: six significant digits, enough for voxel coordinates.
std::string json_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string json_cell(const std::optional<Cell>& c) {
  if (!c) return "null";
  std::ostringstream out;
  out << '[' << c->x << ',' << c->y << ',' << c->z << ']';
  return out.str();
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t{bytes[i]} << 16) | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                            (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += kDigits[(n >> 18) & 63];
    out += kDigits[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

// The surface cubes as runs along the grid of cubes' index order (x fastest, then y, then z):
// alternately a run of cubes not drawn and one of cubes drawn, the first possibly empty, each
// length an unsigned LEB128 number. A wall's surface is a few runs per row, however long.
std::vector<std::uint8_t> cube_runs(const VoxelSurface& surface) {
  std::vector<std::uint8_t> bytes;
  auto put = [&bytes](std::uint64_t n) {
    do {
      bytes.push_back(static_cast<std::uint8_t>((n & 0x7f) | (n >= 0x80 ? 0x80 : 0)));
      n >>= 7;
    } while (n);
  };
  std::uint64_t next = 0;  // the index after the last run
  const auto& cubes = surface.cubes();
  for (std::size_t i = 0; i < cubes.size();) {
    const auto index = [&surface](Cell c) {
      return (std::uint64_t(c.z) * std::uint64_t(surface.height()) + std::uint64_t(c.y)) *
                 std::uint64_t(surface.width()) +
             std::uint64_t(c.x);
    };
    const std::uint64_t first = index(cubes[i]);
    std::size_t end = i + 1;
    while (end < cubes.size() && index(cubes[end]) == first + (end - i)) ++end;
    put(first - next);
    put(end - i);
    next = first + (end - i);
    i = end;
  }
  return bytes;
}

// The world's data for the page's script (drawing/src/voxel_page.js reads it).
std::string world_json(const VoxelWorldView& view, const VoxelSurface& surface, const VoxelHtmlOptions& options) {
  const Map& map = view.map;
  std::ostringstream out;
  out << "{\"title\":" << json_string(view_title(view)) << ",\"size\":[" << map.width() << ',' << map.height() << ','
      << map.depth() << "],\"cell\":" << surface.cell() << ",\"grid\":[" << surface.width() << ',' << surface.height()
      << ',' << surface.depth() << "],\"cubeCount\":" << surface.cubes().size()
      << ",\"cubes\":" << json_string(base64(cube_runs(surface))) << ",\"path\":[";
  for (std::size_t i = 0; i < view.path.size(); ++i)
    out << (i ? "," : "") << json_number(view.path[i].x()) << ',' << json_number(view.path[i].y()) << ','
        << json_number(view.path[i].z());
  out << "],\"gridPath\":[";
  for (std::size_t i = 0; i < view.grid_path.size(); ++i)
    out << (i ? "," : "") << view.grid_path[i].x << ',' << view.grid_path[i].y << ',' << view.grid_path[i].z;
  out << "],\"start\":" << json_cell(view.start) << ",\"goal\":" << json_cell(view.goal) << ",\"pheromone\":[";
  // The strongest first (ties by position, so that the page does not depend on the input's order),
  // as [x, y, z, amount relative to the strongest] flattened.
  auto pheromone = view.pheromone;
  std::erase_if(pheromone, [](const auto& p) { return !(p.second > 0); });
  std::sort(pheromone.begin(), pheromone.end(), [](const auto& a, const auto& b) {
    if (a.second != b.second) return a.second > b.second;
    return std::tie(a.first.z, a.first.y, a.first.x) < std::tie(b.first.z, b.first.y, b.first.x);
  });
  if (pheromone.size() > options.max_pheromone) pheromone.resize(options.max_pheromone);
  for (std::size_t i = 0; i < pheromone.size(); ++i) {
    const auto& [c, amount] = pheromone[i];
    out << (i ? "," : "") << c.x << ',' << c.y << ',' << c.z << ',' << json_number(amount / pheromone[0].second);
  }
  out << "],\"colours\":{\"start\":\"" << colours::kStart << "\",\"goal\":\"" << colours::kGoal << "\",\"path\":\""
      << colours::kPath << "\",\"gridPath\":\"" << colours::kGridPath << "\",\"voxelLow\":\"" << colours::kVoxelLow
      << "\",\"voxelHigh\":\"" << colours::kVoxelHigh << "\",\"pheromoneWeak\":\"" << colours::kPheromoneWeak
      << "\",\"pheromoneStrong\":\"" << colours::kPheromoneStrong << "\",\"frame\":\"" << colours::kFrame << "\"}}";
  return out.str();
}

std::string with_commas(std::int64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// The legend: what each colour is, and how many voxels the cubes are.
std::string legend_html(const VoxelWorldView& view, const VoxelSurface& surface, std::size_t pheromone_drawn) {
  std::ostringstream out;
  auto entry = [&out](const std::string& swatch_style, const std::string& label) {
    out << "<li><span class=\"swatch\" style=\"" << swatch_style << "\"></span>" << label << "</li>\n";
  };
  const std::string round = ";border-radius:50%";
  out << "<ul id=\"legend\">\n";
  if (view.start)
    entry(std::string("background:") + colours::kStart + round, "start " + view.map.describe(*view.start));
  if (view.goal) entry(std::string("background:") + colours::kGoal + round, "goal " + view.map.describe(*view.goal));
  if (!view.path.empty()) entry(std::string("background:") + colours::kPath + ";height:5px", "path");
  if (!view.grid_path.empty())
    entry(std::string("background:") + colours::kGridPath + ";height:2px", "grid path (voxel to voxel)");
  entry(std::string("background:linear-gradient(90deg,") + colours::kVoxelLow + "," + colours::kVoxelHigh + ")",
        "blocked voxels, low to high");
  if (pheromone_drawn)
    entry(std::string("background:linear-gradient(90deg,") + colours::kPheromoneWeak + "," + colours::kPheromoneStrong +
              ")" + round,
          "pheromone, weak to strong (" + with_commas(std::int64_t(pheromone_drawn)) + " voxels)");
  out << "</ul>\n";
  out << "<p id=\"counts\">" << view.map.width() << " &#215; " << view.map.height() << " &#215; " << view.map.depth()
      << " voxels, " << with_commas(surface.blocked_voxels()) << " blocked; drawn: the "
      << with_commas(surface.surface_voxels()) << " on the surface</p>\n";
  if (surface.cell() > 1)
    out << "<p id=\"coarse\">More than the page draws: each cube is " << surface.cell() << " &#215; " << surface.cell()
        << " &#215; " << surface.cell() << " voxels, blocked where any of them is ("
        << with_commas(std::int64_t(surface.cubes().size())) << " cubes).</p>\n";
  return out.str();
}

// The legend in a column on the left, the 3D view right of it.
constexpr const char* kStyle = R"(html,body{margin:0;height:100%;overflow:hidden;background:#fafafa;
font:13px/1.35 sans-serif;color:#212121}
#view{position:absolute;top:0;left:280px;width:calc(100% - 280px);height:100%;display:block}
#panel{position:absolute;top:0;left:0;bottom:0;width:280px;box-sizing:border-box;overflow-y:auto;
padding:10px 12px;background:#fff;border-right:1px solid #ddd}
#panel h1{font-size:15px;margin:0 0 6px;overflow-wrap:anywhere}
#legend{list-style:none;margin:0;padding:0}
#legend li{margin:3px 0}
.swatch{display:inline-block;width:22px;height:12px;margin-right:6px;vertical-align:middle}
#panel p{margin:6px 0}
#help,#counts,#coarse{color:#555}
#status.error{color:#b71c1c;font-weight:bold}
)";

// Makes three.js importable as 'three' from the page itself: each vendored file becomes a blob
// URL, its imports pointed at the others', and an import map names them. No network, and it
// works from file:// too.
constexpr const char* kLoader = R"(<script>
(() => {
  const text = (id) => document.getElementById(id).textContent;
  const url = (code) => URL.createObjectURL(new Blob([code], {type: 'text/javascript'}));
  const core = url(text('three-core'));
  const three = url(text('three-module').replaceAll('"./three.core.min.js"', JSON.stringify(core)));
  const orbit = url(text('orbit-controls').replaceAll("from 'three'", 'from ' + JSON.stringify(three)));
  const map = document.createElement('script');
  map.type = 'importmap';
  map.textContent = JSON.stringify({imports: {'three': three, 'three/addons/controls/OrbitControls.js': orbit}});
  document.currentScript.after(map);
})();
</script>
)";

// An embedded file as the content of a <script> element, which ends at the first "</script".
void script_text(std::ostream& out, const char* id, const char* type, std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (lower.find("</script") != std::string::npos || lower.find("<!--") != std::string::npos)
    throw Error(std::string("the 3D page's embedded script '") + id + "' holds '</script' or '<!--'");
  out << "<script";
  if (*id) out << " id=\"" << id << '"';
  out << " type=\"" << type << "\">\n" << text << "\n</script>\n";
}

}  // namespace

std::string render_voxel_html(const VoxelWorldView& view, const VoxelHtmlOptions& options) {
  const VoxelSurface surface(view.map, options.max_cubes);
  const std::string title = xml_escape(view_title(view));
  std::size_t pheromone_drawn = 0;
  for (const auto& p : view.pheromone) pheromone_drawn += p.second > 0 ? 1 : 0;
  pheromone_drawn = std::min(pheromone_drawn, options.max_pheromone);
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<meta name=\"generator\" content=\"aco voxel page (three.js r185)\">\n<title>" << title
      << "</title>\n<style>\n"
      << kStyle << "</style>\n</head>\n<body>\n<canvas id=\"view\"></canvas>\n<div id=\"panel\">\n<h1>" << title
      << "</h1>\n"
      << legend_html(view, surface, pheromone_drawn)
      << "<p><label><input type=\"checkbox\" id=\"see-through\"> see-through obstacles</label></p>\n"
      << "<p><label>layers up to z = <span id=\"top-layer\">" << view.map.depth() - 1
      << "</span><br><input type=\"range\" id=\"layers\" min=\"0\" max=\"" << view.map.depth() - 1 << "\" value=\""
      << view.map.depth() - 1 << "\" style=\"width:100%\"></label></p>\n"
      << "<p id=\"help\">z points up. Drag: turn; right-drag: move; wheel: zoom.</p>\n"
      << "<p id=\"status\">Loading the 3D view&#8230;</p>\n</div>\n";
  script_text(out, "world", "application/json", world_json(view, surface, options));
  script_text(out, "three-core", "text/plain", embedded::three_core_js());
  script_text(out, "three-module", "text/plain", embedded::three_module_js());
  script_text(out, "orbit-controls", "text/plain", embedded::orbit_controls_js());
  out << kLoader;
  script_text(out, "", "module", embedded::voxel_page_js());
  out << "</body>\n</html>\n";
  return out.str();
}

void write_voxel_html(const std::filesystem::path& file, const VoxelWorldView& view, const VoxelHtmlOptions& options) {
  write_output_file(file, render_voxel_html(view, options), "HTML");
}

}  // namespace aco
