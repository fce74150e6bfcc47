# The web build (preset web, docs/web.md): the same C++ compiled to
# WebAssembly by Debian's Emscripten. Included from the top CMakeLists.txt in
# place of its find_package calls.
#
# Emscripten compiles against its own system root, so Debian's libraries
# cannot be linked, and /usr/include cannot be on the include path (its C
# library headers would shadow Emscripten's). The header-only libraries the
# framework uses are linked one by one into BUILD/web-include instead and
# offered under the targets the native build finds. What the web build does
# without:
#   - OpenImageIO (compiled for the host only): util/image_codec_web.cpp
#     encodes and decodes with stb (PNG, JPEG, HDR and the rest stb_image
#     reads) and tinyexr (EXR), behind the same util/image_codec.h.
#   - pugixml (Debian ships it compiled, without its sources): no COLLADA
#     scenes; loading a .dae says so (scene/collada_web.cpp).
#   - the validity matrix, the suites and the grader: they run natively.

set(PATHLAB_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${PATHLAB_WEB_INCLUDE})

# pathlab_web_header(TARGET PATH...): the Debian headers or header folders
# PATH (under /usr/include) as the include-only target TARGET.
function(pathlab_web_header target)
  foreach(path IN LISTS ARGN)
    if(NOT EXISTS /usr/include/${path})
      message(FATAL_ERROR "the web build needs /usr/include/${path}: install the packages of tools/packages.sh "
                          "(pathlab_web), or docs/web.md")
    endif()
    file(CREATE_LINK /usr/include/${path} ${PATHLAB_WEB_INCLUDE}/${path} SYMBOLIC)
  endforeach()
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  target_include_directories(${target} SYSTEM INTERFACE ${PATHLAB_WEB_INCLUDE})
endfunction()

pathlab_web_header(glm::glm glm)
pathlab_web_header(nlohmann_json::nlohmann_json nlohmann)
pathlab_web_header(CLI11::CLI11 CLI)
pathlab_web_header(FastFloat::fast_float fast_float)
pathlab_web_header(pathlab_web_codecs stb tinyexr.h)
set(FastFloat_FOUND TRUE)

# Threads: WebAssembly's shared memory. Every object is compiled for it, and
# a program's main() runs on a worker of its own (PROXY_TO_PTHREAD), so it
# may wait for its render threads as it does natively.
add_compile_options(-pthread)
# WebAssembly's 128-bit SIMD, with SSE2's intrinsics on it: render/lanes.h's
# four lanes as on x86-64 (Chrome 91, Firefox 89 and Safari 16.4 have it).
add_compile_options(-msimd128 -msse2)
# C++ exceptions caught (Emscripten's default throws them uncatchable).
# Emscripten's JavaScript-based handling: with 3.1.6 and Node.js 20, a throw
# under -fwasm-exceptions went uncaught.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)
# What its C++ library (libc++ 14) lacks: framework/util/web/std_compat.h.
add_compile_options("SHELL:-include ${CMAKE_SOURCE_DIR}/framework/util/web/std_compat.h")
add_link_options(-pthread "SHELL:-s PROXY_TO_PTHREAD=1" "SHELL:-s ALLOW_MEMORY_GROWTH=1"
                 "SHELL:-s MAXIMUM_MEMORY=4GB" "SHELL:-s EXIT_RUNTIME=1"
                 # Node.js: the real file system, as a native program sees it.
                 "SHELL:-s NODERAWFS=1")
add_library(Threads::Threads INTERFACE IMPORTED GLOBAL)

# No window yet: the GUI on WebGL 2 is the next step of the web build (docs/web.md).
set(PATHLAB_HAVE_GUI OFF)
set(PATHLAB_BUILD_TESTS OFF)
set(PATHLAB_BUILD_VALIDITY OFF)
