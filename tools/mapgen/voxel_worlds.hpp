// aco_mapgen --voxel: generated voxel worlds (city, forest, caves) as Moving AI .3dmap files.
#pragma once

#include <filesystem>
#include <string>

namespace mapgen {

// --voxel KIND SIZE SEED OUTDIR [COUNT]: OUTDIR/<kind><W>x<H>x<D>-s<SEED>.3dmap and, with COUNT
// above 0, its .3dmap.3dscen; an Error for a bad KIND, SIZE, SEED or COUNT.
void write_voxel_world(const std::string& kind, const std::string& size_text, const std::string& seed_text,
                       const std::filesystem::path& dir, int count);

}  // namespace mapgen
