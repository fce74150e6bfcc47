# The window's libraries: GLFW, OpenGL and Dear ImGui (with its GLFW and
# OpenGL 3 backends), gathered in the interface target pathlab_gui_libraries.
# Sets PATHLAB_HAVE_GUI: without them everything but the window builds.
#
# Dear ImGui is taken from, in order:
#   1. an installed copy of version 1.86 found by pkg-config (Debian 12's
#      libimgui-dev);
#   2. when PATHLAB_FETCH_IMGUI is ON and there is none (Homebrew has no
#      Dear ImGui; other systems package other versions): the pinned release
#      below, downloaded by FetchContent and checked against its SHA-256.
#      ALWAYS skips step 1 (CI builds the window this way too).
# The default is OFF on Linux, where the distributions package it: the
# Debian build never downloads anything.
if(APPLE OR WIN32)
  set(_pathlab_fetch_default ON)
else()
  set(_pathlab_fetch_default OFF)
endif()
set(PATHLAB_FETCH_IMGUI ${_pathlab_fetch_default} CACHE STRING
    "Build Dear ImGui from its pinned release when none is installed: OFF, ON or ALWAYS")
set_property(CACHE PATHLAB_FETCH_IMGUI PROPERTY STRINGS OFF ON ALWAYS)

# Dear ImGui 1.86, the version Debian 12 packages (the GUI is written against
# its API): Debian's copy of the release (upstream's tag v1.86 with files
# Debian may not ship removed; the backends are all there).
set(PATHLAB_IMGUI_URL "https://deb.debian.org/debian/pool/main/i/imgui/imgui_1.86+ds.orig.tar.xz")
set(PATHLAB_IMGUI_SHA256 0dace0e8e57d298eb6e93af12dc19420cb96330832f6495c733b90aeeef11f64)

find_package(glfw3 3.3 QUIET)
find_package(OpenGL QUIET)
add_library(pathlab_gui_libraries INTERFACE)

# Dear ImGui changes its API from release to release, and the window is
# built and tested against 1.86 only: an installed copy of another version
# is passed over (the pinned release is used when fetching is allowed).
set(_pathlab_imgui "")
set(PATHLAB_IMGUI_SKIPPED "")
if(NOT PATHLAB_FETCH_IMGUI STREQUAL "ALWAYS")
  pkg_check_modules(imgui QUIET IMPORTED_TARGET GLOBAL imgui)
  if(imgui_FOUND AND imgui_VERSION MATCHES "^1\\.86([^0-9]|$)")
    # Debian keeps the backends in a subfolder; the code includes them by name.
    target_include_directories(pathlab_gui_libraries INTERFACE ${imgui_INCLUDEDIR}/backends)
    set(_pathlab_imgui PkgConfig::imgui)
    set(PATHLAB_IMGUI_FROM "${imgui_VERSION}, installed")
  elseif(imgui_FOUND)
    set(PATHLAB_IMGUI_SKIPPED "the installed Dear ImGui is ${imgui_VERSION}, the window needs 1.86: ")
  endif()
endif()

if(NOT _pathlab_imgui AND PATHLAB_FETCH_IMGUI MATCHES "^(ON|ALWAYS)$" AND glfw3_FOUND AND OpenGL_FOUND)
  include(FetchContent)
  FetchContent_Declare(pathlab_imgui URL ${PATHLAB_IMGUI_URL} URL_HASH SHA256=${PATHLAB_IMGUI_SHA256})
  FetchContent_MakeAvailable(pathlab_imgui)  # no CMakeLists.txt inside: only unpacked
  set(src ${pathlab_imgui_SOURCE_DIR})
  add_library(pathlab_imgui STATIC ${src}/imgui.cpp ${src}/imgui_draw.cpp ${src}/imgui_tables.cpp
              ${src}/imgui_widgets.cpp ${src}/backends/imgui_impl_glfw.cpp ${src}/backends/imgui_impl_opengl3.cpp)
  # Made before the project's warning flags are set, its headers seen as
  # system headers: upstream's warnings are not ours to fix.
  target_include_directories(pathlab_imgui SYSTEM PUBLIC ${src} ${src}/backends)
  target_link_libraries(pathlab_imgui PUBLIC glfw OpenGL::GL)
  # Dear ImGui is C++11 code: C++20 deprecates its mixed-enum flags.
  set_target_properties(pathlab_imgui PROPERTIES CXX_STANDARD 17)
  if(APPLE)
    target_compile_definitions(pathlab_imgui PUBLIC GL_SILENCE_DEPRECATION)
  endif()
  set(_pathlab_imgui pathlab_imgui)
  set(PATHLAB_IMGUI_FROM "1.86, built from ${PATHLAB_IMGUI_URL}")
endif()

if(glfw3_FOUND AND OpenGL_FOUND AND _pathlab_imgui)
  set(PATHLAB_HAVE_GUI ON)
  target_link_libraries(pathlab_gui_libraries INTERFACE glfw OpenGL::GL ${_pathlab_imgui} ${CMAKE_DL_LIBS})
else()
  set(PATHLAB_HAVE_GUI OFF)
endif()
