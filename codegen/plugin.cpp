#include "codegen/plugin.h"

#include "codegen/object_file.h"

extern "C" const mbc::codegen::Plugin* mbc_codegen_plugin() {
  static const mbc::codegen::Plugin plugin{&mbc::codegen::writeCompiled};
  return &plugin;
}
