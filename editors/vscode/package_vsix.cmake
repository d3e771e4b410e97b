# Builds the VS Code extension's .vsix: the extension's files copied into
# OUT_DIR with mbc's version in package.json, the packages
# package-lock.json pins (npm ci checks their integrity), then vsce
# packages it. Without the registry (no network, a certificate npm does not
# trust) the build goes on without the .vsix and says why; removing OUT_DIR
# tries again.
#   cmake -DNPM=... -DSOURCE_DIR=... -DOUT_DIR=... -DVERSION=... -DVSIX=...
#         -DSTAMP=... -P package_vsix.cmake
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
file(COPY ${SOURCE_DIR}/ DESTINATION ${OUT_DIR} PATTERN *.cmake EXCLUDE
     PATTERN node_modules EXCLUDE PATTERN *.vsix EXCLUDE)
file(READ ${OUT_DIR}/package.json manifest)
string(REGEX REPLACE "\"version\": \"[^\"]*\"" "\"version\": \"${VERSION}\""
       manifest "${manifest}")
file(WRITE ${OUT_DIR}/package.json "${manifest}")
execute_process(
  COMMAND ${NPM} ci --ignore-scripts --no-audit --no-fund --prefix ${OUT_DIR}
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  # npm 9 writes "npm ERR! code ...", npm 10 and later "npm error code ...".
  string(REGEX MATCH "npm (ERR!|error) code [^\n]*" why "${output}")
  message(WARNING "npm could not fetch the VS Code extension's packages "
                  "(${why}): mbc is built without its .vsix. Remove ${OUT_DIR} "
                  "to try again.")
  file(WRITE ${STAMP} "npm ci failed: ${why}\n")
  return()
endif()
execute_process(
  COMMAND ${OUT_DIR}/node_modules/.bin/vsce package --skip-license
          --allow-missing-repository --out ${VSIX}
  WORKING_DIRECTORY ${OUT_DIR}
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "vsce could not package the VS Code extension:\n${output}")
endif()
file(WRITE ${STAMP} "")
