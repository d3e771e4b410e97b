/* mbc's version, written here only: CMakeLists.txt reads these three lines
 * for the project and its CMake package. MBC_VERSION is the number to
 * compare (10203 for 1.2.3); mbrt_version() gives the string of the library
 * a program is linked with, which may be newer than its header. */
#ifndef MBC_VERSION_H
#define MBC_VERSION_H

#define MBC_VERSION_MAJOR 0
#define MBC_VERSION_MINOR 1
#define MBC_VERSION_PATCH 0

#define MBC_VERSION                                                            \
  (MBC_VERSION_MAJOR * 10000 + MBC_VERSION_MINOR * 100 + MBC_VERSION_PATCH)
#define MBC_VERSION_TEXT_(n) #n
#define MBC_VERSION_TEXT(n) MBC_VERSION_TEXT_(n)
#define MBC_VERSION_STRING                                                     \
  MBC_VERSION_TEXT(MBC_VERSION_MAJOR)                                          \
  "." MBC_VERSION_TEXT(MBC_VERSION_MINOR) "." MBC_VERSION_TEXT(                \
      MBC_VERSION_PATCH)

#endif /* MBC_VERSION_H */
