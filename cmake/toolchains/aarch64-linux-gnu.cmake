# Cross-compiling for 64-bit Arm Linux (Apple Silicon's instruction set) with
# Debian's cross compiler, against a Debian arm64 root folder that holds the
# libraries (tools/aarch64-check makes one with mmdebstrap).
#   cmake -S . -B build-aarch64 -G Ninja --toolchain cmake/toolchains/aarch64-linux-gnu.cmake \
#         -DPATHLAB_AARCH64_SYSROOT=/path/to/sysroot
# Executables then run under qemu-user (CMAKE_CROSSCOMPILING_EMULATOR).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

set(PATHLAB_AARCH64_SYSROOT "$ENV{PATHLAB_AARCH64_SYSROOT}" CACHE PATH "Debian arm64 root folder")
if(NOT IS_DIRECTORY "${PATHLAB_AARCH64_SYSROOT}/usr/lib/aarch64-linux-gnu")
  message(FATAL_ERROR "PATHLAB_AARCH64_SYSROOT='${PATHLAB_AARCH64_SYSROOT}' is not a Debian arm64 root (tools/aarch64-check makes one)")
endif()
# Toolchain files are read again by try_compile projects: pass the root on.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES PATHLAB_AARCH64_SYSROOT)
set(CMAKE_SYSROOT "${PATHLAB_AARCH64_SYSROOT}")

# Libraries, headers and CMake packages from the root; programs from this machine.
set(CMAKE_FIND_ROOT_PATH "${PATHLAB_AARCH64_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(ENV{PKG_CONFIG_SYSROOT_DIR} "${PATHLAB_AARCH64_SYSROOT}")
set(ENV{PKG_CONFIG_LIBDIR}
    "${PATHLAB_AARCH64_SYSROOT}/usr/lib/aarch64-linux-gnu/pkgconfig:${PATHLAB_AARCH64_SYSROOT}/usr/share/pkgconfig")

# ctest runs the tests through qemu; QEMU_LD_PREFIX also reaches the
# candidate processes the suites start (binfmt_misc runs those through qemu).
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64-static -L "${PATHLAB_AARCH64_SYSROOT}")
