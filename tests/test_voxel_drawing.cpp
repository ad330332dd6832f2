// The pictures of a voxel world (issue 42): the surface voxels they draw, the 3D HTML page
// (aco/drawing/voxel_html.hpp; tests/voxel_page_in_chromium.sh opens it) and the isometric and sliced SVG
// (aco/drawing/voxel_svg.hpp).
#include <catch2/catch.hpp>

#include <regex>
#include <string>
#include <vector>

#include "aco/error.hpp"
#include "aco/voxel.hpp"
#include "aco/drawing/voxel_html.hpp"
#include "aco/drawing/voxel_svg.hpp"

using Catch::Contains;

namespace {

void block(aco::VoxelMap& world, int x0, int x1, int y0, int y1, int z0, int z1) {
  for (int z = z0; z <= z1; ++z)
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) world.set_blocked({x, y, z}, true);
}

// A 10 x 8 x 6 world: a ground, a wall at x = 5 up to z = 3, and a path over it.
struct Sample {
  aco::VoxelMap world{10, 8, 6, "sample"};
  aco::VoxelWorldView view{world};
  Sample() {
    block(world, 0, 9, 0, 7, 0, 0);
    block(world, 5, 5, 0, 7, 1, 3);
    view.start = aco::Cell{1, 4, 1};
    view.goal = aco::Cell{8, 4, 1};
    view.path = {{1, 4, 1}, {4, 4, 4}, {6, 4, 4}, {8, 4, 1}};
    view.grid_path = {{1, 4, 1}, {2, 4, 2}, {3, 4, 3}, {4, 4, 4}, {5, 4, 4},
                      {6, 4, 4}, {7, 4, 3}, {8, 4, 2}, {8, 4, 1}};
    view.pheromone = {{{2, 4, 2}, 3.0}, {{3, 4, 3}, 6.0}, {{7, 4, 3}, 0.0}};
  }
};

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

std::string json_field(const std::string& page, const std::string& name) {
  std::smatch m;
  REQUIRE(std::regex_search(page, m, std::regex("\"" + name + "\":(\"[^\"]*\"|\\[[^\\]]*\\]|[0-9]+)")));
  return m[1];
}

// The page's runs of surface cubes (voxel_html.cpp's cube_runs) decoded: the indices drawn.
std::vector<std::uint64_t> decode_cubes(std::string base64) {
  base64 = base64.substr(1, base64.size() - 2);
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> bytes;
  std::uint32_t bits = 0;
  int held = 0;
  for (char c : base64) {
    if (c == '=') break;
    bits = (bits << 6) | std::uint32_t(digits.find(c));
    held += 6;
    if (held >= 8) {
      held -= 8;
      bytes.push_back(std::uint8_t(bits >> held));
    }
  }
  std::vector<std::uint64_t> cubes;
  std::uint64_t index = 0;
  bool drawn = false;
  for (std::size_t i = 0; i < bytes.size();) {
    std::uint64_t run = 0;
    for (int shift = 0;; shift += 7) {
      run |= std::uint64_t(bytes[i] & 0x7f) << shift;
      if (!(bytes[i++] & 0x80)) break;
    }
    for (std::uint64_t k = 0; drawn && k < run; ++k) cubes.push_back(index + k);
    index += run;
    drawn = !drawn;
  }
  return cubes;
}

// Well-formed XML as far as an SVG of ours goes: tags balanced and nested, attributes quoted.
void require_well_formed(const std::string& svg) {
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([a-zA-Z][a-zA-Z0-9-]*)((?:\s+[a-zA-Z:][a-zA-Z0-9:-]*="[^"<]*")*)\s*(/?)>)");
  std::size_t at = 0, tags = 0;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), tag); it != std::sregex_iterator(); ++it, ++tags) {
    const auto& m = *it;
    INFO("at " << m.position() << ": " << m.str());
    REQUIRE(svg.substr(at, m.position() - at).find('<') == std::string::npos);  // no tag left unmatched
    at = m.position() + m.length();
    if (m[1] == "/") {
      REQUIRE(!open.empty());
      REQUIRE(open.back() == m[2]);
      open.pop_back();
    } else if (m[4] != "/") {
      open.push_back(m[2]);
    }
  }
  REQUIRE(tags > 0);
  REQUIRE(open.empty());
  REQUIRE(svg.substr(at).find('<') == std::string::npos);
}

}  // namespace

TEST_CASE("a voxel world's surface: blocked voxels with a free neighbour or on the boundary", "[voxel][drawing]") {
  aco::VoxelMap world(6, 6, 6, "block");
  block(world, 1, 4, 1, 4, 1, 4);  // 4 x 4 x 4 inside: its 2 x 2 x 2 core is hidden
  const aco::VoxelSurface inner(world, 1000);
  CHECK(inner.cell() == 1);
  CHECK(inner.blocked_voxels() == 64);
  CHECK(inner.surface_voxels() == 56);
  CHECK(inner.cubes().size() == 56);
  CHECK(inner.cubes().front() == aco::Cell{1, 1, 1});

  aco::VoxelMap solid(3, 3, 3, "solid");
  block(solid, 0, 2, 0, 2, 0, 2);
  CHECK(aco::VoxelSurface(solid, 1000).cubes().size() == 26);  // all but the centre touch the boundary

  SECTION("more surface than max_cubes: coarser cubes, blocked where any voxel is") {
    aco::VoxelMap big(40, 40, 20, "big");
    block(big, 0, 39, 0, 39, 0, 0);
    big.set_blocked({39, 39, 19}, true);
    const aco::VoxelSurface coarse(big, 500);
    CHECK(coarse.cell() == 2);
    CHECK(coarse.width() == 20);
    CHECK(coarse.depth() == 10);
    CHECK(coarse.surface_voxels() == 1601);
    CHECK(coarse.cubes().size() <= 500);
    CHECK(coarse.blocked({19, 19, 9}));  // the lone voxel keeps its cube
    CHECK_FALSE(coarse.blocked({18, 19, 9}));
  }
}

TEST_CASE("the 3D page is one file: three.js inside, the world's data, a legend, deterministic", "[voxel][drawing]") {
  Sample s;
  s.view.title = "over the wall </script> & back";
  const std::string page = aco::render_voxel_html(s.view);
  CHECK(page == aco::render_voxel_html(s.view));
  CHECK_THAT(page, Contains("<title>over the wall &lt;/script&gt; &amp; back</title>"));
  CHECK_THAT(page, Contains("\"title\":\"over the wall \\u003c/script> & back\""));
  // The world's data, three.js's two files, OrbitControls, the loader and the page's module.
  CHECK(count(page, "</script>") == 6);
  CHECK(count(page, "<script type=\"module\">") == 1);
  CHECK_THAT(page, Contains("const t=\"185\""));  // three.js r185's REVISION
  CHECK_THAT(page, Contains("class OrbitControls"));
  CHECK_THAT(page, Contains("new THREE.InstancedMesh"));
  // Nothing fetched from elsewhere: no script, style sheet or image by address.
  CHECK(count(page, "<script src") == 0);
  CHECK(count(page, "<link") == 0);
  CHECK(count(page, "<img") == 0);
  // The legend names what is drawn.
  CHECK_THAT(page, Contains("start (1,4,1)"));
  CHECK_THAT(page, Contains("goal (8,4,1)"));
  CHECK_THAT(page, Contains("grid path"));
  CHECK_THAT(page, Contains("pheromone, weak to strong (2 voxels)"));  // the zero is left out
  CHECK_THAT(page, Contains("10 &#215; 8 &#215; 6 voxels, 104 blocked; drawn: the 104 on the surface"));
  CHECK(page.find("id=\"coarse\"") == std::string::npos);
  // The data: the path, the pheromone relative to the strongest, the surface cubes as runs.
  CHECK(json_field(page, "size") == "[10,8,6]");
  CHECK(json_field(page, "path") == "[1,4,1,4,4,4,6,4,4,8,4,1]");
  CHECK(json_field(page, "pheromone") == "[3,4,3,1,2,4,2,0.5]");
  CHECK(json_field(page, "start") == "[1,4,1]");
  const auto cubes = decode_cubes(json_field(page, "cubes"));
  const aco::VoxelSurface surface(s.world, 1000);
  REQUIRE(cubes.size() == surface.cubes().size());
  for (std::size_t i = 0; i < cubes.size(); ++i) {
    const auto& c = surface.cubes()[i];
    CHECK(cubes[i] == std::uint64_t((c.z * 8 + c.y) * 10 + c.x));
  }

  SECTION("a surface over max_cubes is drawn coarser, and the page says so") {
    aco::VoxelHtmlOptions options;
    options.max_cubes = 40;
    const std::string coarse = aco::render_voxel_html(s.view, options);
    CHECK(json_field(coarse, "cell") == "2");
    CHECK(json_field(coarse, "grid") == "[5,4,3]");
    CHECK_THAT(coarse, Contains("each cube is 2 &#215; 2 &#215; 2 voxels, blocked where any of them is (24 cubes)"));
  }
}

TEST_CASE("a voxel world's SVG: isometric cubes back to front, the path on top, slices, deterministic",
          "[voxel][drawing]") {
  Sample s;
  s.view.title = "sample <3>";
  aco::VoxelSvgStyle style;
  style.slices = {1, 4};
  const std::string svg = aco::render_voxel_svg(s.view, style);
  CHECK(svg == aco::render_voxel_svg(s.view, style));
  require_well_formed(svg);
  CHECK_THAT(svg, Contains(">sample &lt;3&gt;</text>"));
  CHECK(count(svg, "<polyline fill=\"none\" id=\"path\"") == 1);
  CHECK(count(svg, "id=\"start\"") == 1);
  CHECK(count(svg, "id=\"goal\"") == 1);
  // The path is drawn after every voxel face.
  CHECK(svg.rfind("<path class=") < svg.find("id=\"path\""));
  // The ground's top shows where the wall does not stand on it: 10 x 8 less the wall's 8.
  CHECK(count(svg, "<path class=\"t0\"") == 72);
  // Two slices: the path crosses z = 1 at both ends, and runs along z = 4 over the wall.
  CHECK(count(svg, "<g class=\"slice\"") == 2);
  CHECK_THAT(svg, Contains("data-z=\"4\""));
  CHECK(count(svg, "class=\"path\"") == 3);
  CHECK(count(svg, "class=\"start\"") == 1);
  CHECK(count(svg, "class=\"goal\"") == 1);

  style.slices = {6};
  CHECK_THROWS_WITH(aco::render_voxel_svg(s.view, style), Contains("slice z = 6 is outside sample"));
  style.isometric = false;
  style.slices = {};
  CHECK_THROWS_AS(aco::render_voxel_svg(s.view, style), aco::Error);
  style.slices = {2};
  const std::string slices_only = aco::render_voxel_svg(s.view, style);
  require_well_formed(slices_only);
  CHECK(slices_only.find("id=\"isometric\"") == std::string::npos);

  // More faces than max_faces: coarser cubes, which the legend says.
  aco::VoxelSvgStyle few;
  few.max_faces = 30;
  const std::string coarse = aco::render_voxel_svg(s.view, few);
  require_well_formed(coarse);
  CHECK(count(coarse, "<path class=") <= 30);
  CHECK_THAT(coarse, Contains("isometric view: each cube is 3 x 3 x 3 voxels, blocked where any of them is"));
  CHECK(svg.find("each cube is") == std::string::npos);

  CHECK(aco::spread_layers(32, 4) == std::vector<int>{0, 10, 20, 31});
  CHECK(aco::spread_layers(3, 5) == std::vector<int>{0, 1, 2});
  CHECK(aco::spread_layers(8, 1) == std::vector<int>{0});
}
