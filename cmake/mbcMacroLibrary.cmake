# mbc_add_macro_library(<target> SOURCES a.nc b.nc ...
#                       [HEADER <name>.h] [TABLE <name>] [OPTIONS <mbc option>...])
#
# Compiles Macro B programs at build time, as protobuf_generate does for
# .proto files: `mbc compile` turns the sources into one object (calls
# between its programs are direct) and a C header declaring an entry point
# mbc_O<number> per program and the program table (mbc_programs_<target>,
# or TABLE). <target> is a static library of that object, linked with
# mbc::runtime (mbc::runtime_shared in a project without C++); its users
# include "<target>.h" (or HEADER).
#
# mbc runs in the current source directory with the sources as written, so
# alarm reports name them the way the CMakeLists.txt does. OPTIONS go to
# `mbc compile` as they are: -O0..-O3, -g, --cpu native, --trace.
function(mbc_add_macro_library target)
  cmake_parse_arguments(PARSE_ARGV 1 MBC "" "HEADER;TABLE" "SOURCES;OPTIONS")
  if(NOT MBC_SOURCES)
    message(FATAL_ERROR "mbc_add_macro_library(${target}): no SOURCES")
  endif()
  if(MBC_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR
            "mbc_add_macro_library(${target}): unknown arguments ${MBC_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT MBC_HEADER)
    set(MBC_HEADER ${target}.h)
  endif()
  string(MAKE_C_IDENTIFIER "${target}" id)
  if(NOT MBC_TABLE)
    set(MBC_TABLE mbc_programs_${id})
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_mbc)
  set(object ${dir}/${id}.o)
  set(header ${dir}/${MBC_HEADER})
  set(inputs)
  foreach(source IN LISTS MBC_SOURCES)
    get_filename_component(path ${source} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND inputs ${path})
  endforeach()
  add_custom_command(
    OUTPUT ${object} ${header}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${dir}
    COMMAND mbc::mbc compile -c ${MBC_SOURCES} -o ${object} --header ${header}
            --table ${MBC_TABLE} ${MBC_OPTIONS}
    DEPENDS mbc::mbc ${inputs}
    WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
    COMMENT "mbc compile ${target}: ${MBC_SOURCES}"
    VERBATIM)
  set_source_files_properties(${object} PROPERTIES EXTERNAL_OBJECT TRUE GENERATED TRUE)
  add_library(${target} STATIC ${object} ${header})
  target_include_directories(${target} PUBLIC ${dir})
  # An object alone says no language. A C++ project links the static
  # runtime; a C project (no C++ linker, no C++ library) the shared one,
  # which brings its C++ library along and exports the C ABI alone.
  get_property(languages GLOBAL PROPERTY ENABLED_LANGUAGES)
  if("CXX" IN_LIST languages)
    set_target_properties(${target} PROPERTIES LINKER_LANGUAGE CXX)
    target_link_libraries(${target} PUBLIC mbc::runtime)
  else()
    set_target_properties(${target} PROPERTIES LINKER_LANGUAGE C)
    # Compiled code calls libm (round), which a C link does not add.
    target_link_libraries(${target} PUBLIC mbc::runtime_shared m)
  endif()
endfunction()
