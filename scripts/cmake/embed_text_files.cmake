# Script mode (cmake -P): writes OUTPUT, a C++ source defining sceneResources() with the text of
# each file of FILES (relative to BASE, separated by '|') as a raw string literal, in that order.
# Each file must be valid JSON; the build stops naming the file otherwise.
set(delimiter "chaplygin_json")
set(body "")
string(REPLACE "|" ";" files "${FILES}")
foreach(name IN LISTS files)
  file(READ "${BASE}/${name}" text)
  string(JSON type ERROR_VARIABLE json_error TYPE "${text}")
  if(json_error)
    message(FATAL_ERROR "${BASE}/${name}: not valid JSON: ${json_error}")
  endif()
  string(FIND "${text}" ")${delimiter}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${BASE}/${name} contains the raw-string delimiter )${delimiter}\"")
  endif()
  string(APPEND body "    {\"${name}\", R\"${delimiter}(${text})${delimiter}\"},\n")
endforeach()
set(source "// Generated at build time by scripts/cmake/embed_text_files.cmake; edit the files it embeds.
#include \"scene/scene_resources.h\"

namespace chaplygin {
namespace {

constexpr SceneResource kFiles[] = {
${body}};

} // namespace

std::span<const SceneResource> sceneResources() { return kFiles; }

} // namespace chaplygin
")
file(WRITE "${OUTPUT}" "${source}")
