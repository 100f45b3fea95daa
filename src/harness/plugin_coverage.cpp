#include "harness/plugin_coverage.h"

#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace mfz {
namespace {

// Where a loaded object lies: its load address, its file, its segments.
struct LoadedObject {
  uintptr_t address = 0;  // the address looked for
  bool found = false;
  uintptr_t base = 0;
  std::string path;
  std::vector<ElfW(Phdr)> segments;
};

int find_object(dl_phdr_info* info, size_t, void* data) {
  auto& object = *static_cast<LoadedObject*>(data);
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& p = info->dlpi_phdr[i];
    const uintptr_t start = info->dlpi_addr + p.p_vaddr;
    if (p.p_type != PT_LOAD || object.address < start || object.address >= start + p.p_memsz) continue;
    object.found = true;
    object.base = info->dlpi_addr;
    object.path = info->dlpi_name ? info->dlpi_name : "";
    object.segments.assign(info->dlpi_phdr, info->dlpi_phdr + info->dlpi_phnum);
    return 1;
  }
  return 0;
}

bool read_at(int fd, void* data, size_t size, off_t offset) {
  return pread(fd, data, size, offset) == static_cast<ssize_t>(size);
}

// The named section's header, read off the file; false when it has none.
bool find_section(const std::string& path, const char* name, ElfW(Shdr)& found) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  bool ok = false;
  ElfW(Ehdr) header;
  if (read_at(fd, &header, sizeof header, 0) && std::memcmp(header.e_ident, ELFMAG, SELFMAG) == 0 &&
      header.e_shentsize == sizeof(ElfW(Shdr)) && header.e_shstrndx < header.e_shnum) {
    std::vector<ElfW(Shdr)> sections(header.e_shnum);
    if (read_at(fd, sections.data(), sizeof(ElfW(Shdr)) * sections.size(), static_cast<off_t>(header.e_shoff))) {
      const ElfW(Shdr)& names = sections[header.e_shstrndx];
      std::vector<char> text(names.sh_size + 1, '\0');
      if (read_at(fd, text.data(), names.sh_size, static_cast<off_t>(names.sh_offset))) {
        for (const ElfW(Shdr)& s : sections) {
          if (s.sh_name >= names.sh_size || std::strcmp(text.data() + s.sh_name, name) != 0) continue;
          found = s;
          ok = true;
          break;
        }
      }
    }
  }
  close(fd);
  return ok;
}

}  // namespace

CoverageCounters coverage_counters_at(const void* address) {
  LoadedObject object;
  object.address = reinterpret_cast<uintptr_t>(address);
  dl_iterate_phdr(find_object, &object);
  ElfW(Shdr) section{};
  if (!object.found || object.path.empty() || !find_section(object.path, "__sancov_cntrs", section) ||
      section.sh_size == 0)
    return {};
  // The counters are written at run time: a section outside the object's
  // writable segments is not what it claims.
  const auto holds_section = [&](const ElfW(Phdr)& p) {
    return p.p_type == PT_LOAD && (p.p_flags & PF_W) && section.sh_addr >= p.p_vaddr &&
           section.sh_addr + section.sh_size <= p.p_vaddr + p.p_memsz;
  };
  if (std::none_of(object.segments.begin(), object.segments.end(), holds_section)) return {};
  return {reinterpret_cast<uint8_t*>(object.base + section.sh_addr), static_cast<size_t>(section.sh_size)};
}

void take_coverage_hits(const CoverageCounters& counters, std::string& message) {
  const size_t shared = std::min(counters.size, kMaxSharedCounters);
  const size_t count_at = message.size();
  uint32_t count = 0;
  message.append(sizeof count, '\0');
  const auto take = [&](size_t i) {
    if (counters.begin[i] == 0) return;
    const uint32_t hit = static_cast<uint32_t>(i) << 8 | counters.begin[i];
    message.append(reinterpret_cast<const char*>(&hit), sizeof hit);
    counters.begin[i] = 0;
    ++count;
  };
  // Most counters are zero after a call: eight are read at once.
  size_t i = 0;
  for (; i + 8 <= shared; i += 8) {
    uint64_t word;
    std::memcpy(&word, counters.begin + i, sizeof word);
    if (word != 0)
      for (size_t k = i; k < i + 8; ++k) take(k);
  }
  for (; i < shared; ++i) take(i);
  if (counters.size > shared) std::memset(counters.begin + shared, 0, counters.size - shared);
  std::memcpy(message.data() + count_at, &count, sizeof count);
}

bool apply_coverage_hits(const CoverageCounters& counters, const uint32_t* hits, size_t count) {
  for (size_t k = 0; k < count; ++k) {
    const size_t index = hits[k] >> 8;
    if (index >= counters.size) return false;
    // A fuzz execution makes several calls: their counts add up, and stop
    // at the top rather than wrap, which would turn many hits into few.
    const unsigned sum = counters.begin[index] + (hits[k] & 0xffu);
    counters.begin[index] = static_cast<uint8_t>(std::min(sum, 255u));
  }
  return true;
}

}  // namespace mfz
