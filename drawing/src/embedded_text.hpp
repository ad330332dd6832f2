#pragma once
// Text compiled into libaco_drawing (cmake/EmbedText.cmake writes the definitions at build time):
// the vendored three.js (third_party/three) and the voxel page's script.
#include <string_view>

namespace aco::embedded {

std::string_view three_core_js();  // three.core.min.js
std::string_view three_module_js();  // three.module.min.js: imports "./three.core.min.js"
std::string_view orbit_controls_js();  // examples/jsm/controls/OrbitControls.js: imports 'three'
std::string_view voxel_page_js();  // drawing/src/voxel_page.js

}  // namespace aco::embedded
