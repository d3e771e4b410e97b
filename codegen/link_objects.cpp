// `ld -r` through posix_spawnp (see link_objects.h).
#include "codegen/link_objects.h"

#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace mbc::codegen {

bool linkRelocatable(const std::vector<std::string>& inputs,
                     const std::string& output, std::string& error) {
  std::vector<std::string> words = {"ld", "-r", "-o", output};
  words.insert(words.end(), inputs.begin(), inputs.end());
  std::vector<char*> argv;
  for (std::string& w : words) {
    argv.push_back(w.data());
  }
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, "ld", nullptr, nullptr, argv.data(), environ) != 0) {
    error = "cannot run the linker 'ld'";
    return false;
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    error = "'ld -r' failed to combine the object's parts";
    return false;
  }
  return true;
}

} // namespace mbc::codegen
