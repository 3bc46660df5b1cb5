# Writes OUT, the definition of tp::app::versionText() (src/cli/build_version.hpp),
# naming the git commit of SOURCE_DIR; run at every build, it rewrites OUT only
# when the text changes, so an unchanged commit rebuilds nothing.
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
endif()
set(text "#include \"cli/build_version.hpp\"\n\nnamespace tp::app {\n\nconst char* versionText() { return \"tidepool ${VERSION} (commit ${commit})\"; }\n\n}  // namespace tp::app\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
