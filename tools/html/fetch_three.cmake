# Fetches three.js at the version tools/html/package-lock.json pins (npm ci
# checks its integrity) into HTML_DIR. Without the registry (no network, a
# certificate npm does not trust) the build goes on without the page of
# --html, which then says why it is missing; removing HTML_DIR tries again.
#   cmake -DNPM=... -DSOURCE_DIR=... -DHTML_DIR=... -DSTAMP=... -P fetch_three.cmake
file(MAKE_DIRECTORY ${HTML_DIR})
file(COPY ${SOURCE_DIR}/package.json ${SOURCE_DIR}/package-lock.json
     DESTINATION ${HTML_DIR})
execute_process(
  COMMAND ${NPM} ci --ignore-scripts --no-audit --no-fund --prefix ${HTML_DIR}
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(status EQUAL 0)
  file(WRITE ${STAMP} "")
else()
  # npm 9 writes "npm ERR! code ...", npm 10 and later "npm error code ...".
  string(REGEX MATCH "npm (ERR!|error) code [^\n]*" why "${output}")
  message(WARNING "npm could not fetch three.js (${why}): mbc is built "
                  "without the page of --html. Remove ${HTML_DIR} to try again.")
  file(WRITE ${STAMP} "npm ci failed: ${why}\n")
endif()
