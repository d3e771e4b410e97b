#include <mbc/read_file.h>

#include <cerrno>
#include <cstdio>
#include <memory>

namespace mbc {

int readFile(const std::string& path, std::string& text) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(
      std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) {
    return errno;
  }
  text.clear();
  char buffer[1 << 16];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, file.get())) {
    text.append(buffer, n);
  }
  if (std::ferror(file.get())) {
    return errno != 0 ? errno : EIO;
  }
  return 0;
}

} // namespace mbc
