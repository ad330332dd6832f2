#include "aco/engine/plugin_compatibility.hpp"

#include <elf.h>
#include <link.h>  // ElfW: the ELF types of this machine's word size

#include <bit>
#include <cstring>
#include <fstream>

#include "aco/error.hpp"
#include "aco/plugin.hpp"

namespace aco {
namespace {

namespace fs = std::filesystem;

class ElfFile {
 public:
  explicit ElfFile(const fs::path& file) : name_(file.string()), in_(file, std::ios::binary) {
    if (!in_) fail("cannot be read");
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::uint64_t>(in_.tellg());
  }

  // The section's bytes; empty if there is no such section.
  std::string section(const std::string& wanted) {
    const auto header = read<ElfW(Ehdr)>(0);
    if (std::memcmp(header.e_ident, ELFMAG, SELFMAG) != 0) fail("is not an ELF file");
    if (header.e_ident[EI_CLASS] != (sizeof(void*) == 8 ? ELFCLASS64 : ELFCLASS32) ||
        header.e_ident[EI_DATA] != (std::endian::native == std::endian::little ? ELFDATA2LSB : ELFDATA2MSB))
      fail("is an ELF file for another word size or byte order than this machine's");
    if (header.e_shentsize != sizeof(ElfW(Shdr))) fail("has malformed section headers");
    const auto section_header = [&](std::uint64_t i) {
      return read<ElfW(Shdr)>(header.e_shoff + i * sizeof(ElfW(Shdr)));
    };
    if (header.e_shstrndx >= header.e_shnum) fail("has no section name table");
    const std::string names = bytes(section_header(header.e_shstrndx));
    for (std::uint64_t i = 0; i < header.e_shnum; ++i) {
      const auto s = section_header(i);
      if (s.sh_name >= names.size() || names.c_str() + s.sh_name != wanted) continue;
      if (s.sh_type != SHT_PROGBITS) fail("has a section " + wanted + " that holds no data");
      return bytes(s);
    }
    return {};
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw Error(name_ + " " + what); }

  template <class T>
  T read(std::uint64_t offset) {
    T value;
    if (offset > size_ || size_ - offset < sizeof(T)) fail("is truncated (an ELF header lies beyond its end)");
    in_.seekg(static_cast<std::streamoff>(offset));
    in_.read(reinterpret_cast<char*>(&value), sizeof(T));
    if (!in_) fail("cannot be read");
    return value;
  }

  std::string bytes(const ElfW(Shdr) & s) {
    if (s.sh_offset > size_ || size_ - s.sh_offset < s.sh_size) fail("is truncated (a section lies beyond its end)");
    std::string data(s.sh_size, '\0');
    in_.seekg(static_cast<std::streamoff>(s.sh_offset));
    in_.read(data.data(), static_cast<std::streamsize>(data.size()));
    if (!in_) fail("cannot be read");
    return data;
  }

  std::string name_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
};

}  // namespace

std::vector<PluginRecord> read_plugin_records(const fs::path& file) {
  const std::string data = ElfFile(file).section(ACO_PLUGIN_RECORD_SECTION);
  std::vector<PluginRecord> records;
  std::size_t at = 0;
  const auto field = [&]() {
    const auto end = data.find('\0', at);
    if (end == std::string::npos)
      throw Error(file.string() + ": a plugin record in section " ACO_PLUGIN_RECORD_SECTION " is cut short");
    std::string value = data.substr(at, end - at);
    at = end + 1;
    return value;
  };
  while (true) {
    at = data.find_first_not_of('\0', at);  // padding the linker put between records
    if (at == std::string::npos) break;
    if (field() != ACO_PLUGIN_RECORD_MAGIC)
      throw Error(file.string() + ": section " ACO_PLUGIN_RECORD_SECTION
                                  " holds something that is not a plugin record");
    PluginRecord r;
    r.abi = field();
    // A record of another ABI version may have other fields: only the first two are read.
    if (r.abi != std::to_string(kPluginAbiVersion)) {
      records.push_back(r);
      break;
    }
    r.stdlib = field();
    r.compiler = field();
    r.build = field();
    r.slot = field();
    r.name = field();
    r.version = field();
    r.summary = field();
    records.push_back(std::move(r));
  }
  return records;
}

std::string incompatibility(const PluginRecord& record) {
  if (record.abi != std::to_string(kPluginAbiVersion))
    return "ABI " + record.abi + ", host expects " + std::to_string(kPluginAbiVersion) +
           " (rebuild the plugin against this framework)";
  if (record.stdlib != kHostStdlib)
    return "built with " + record.stdlib + " (compiler " + record.compiler + "), this host with " + kHostStdlib +
           ": their std::string and containers differ (rebuild the plugin with the host's standard library settings)";
  return {};
}

}  // namespace aco
