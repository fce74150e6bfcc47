# The Debian 12 packages PathLab needs, by purpose: the one list every
# script installs from (sourced by quickstart.sh, hardening.sh, make-report
# and the Gradescope setup.sh).
#   source tools/packages.sh; install_packages "${pathlab_build[@]}" "${pathlab_test[@]}"

# What the grader builds the suites with (Gradescope installs only these).
pathlab_core=(build-essential cmake ninja-build pkg-config python3 libglm-dev libopenimageio-dev
              doctest-dev nlohmann-json3-dev libcli11-dev libpugixml-dev)
# The whole project: the core, Embree for the benchmark, GLFW and Dear ImGui for the GUI, plots,
# fast_float (the OBJ reader's numbers: optional with GCC, needed with libc++; Ubuntu 22.04 lacks it).
pathlab_build=("${pathlab_core[@]}" git libembree-dev libglfw3-dev libimgui-dev python3-matplotlib libfast-float-dev)
# The write-up (tools/writeup): Markdown for the students' answers, Chromium to print the PDF.
pathlab_writeup=(python3-markdown chromium)
# The web build (preset web, docs/web.md): Emscripten (it brings Node.js), and the
# header-only image codecs it compiles in place of OpenImageIO.
pathlab_web=(emscripten libstb-dev libtinyexr-dev)
# The tests: the GUI on a virtual display (Xvfb, Mesa's software OpenGL) looked
# at with ImageMagick, the grader's sandbox (bubblewrap; libseccomp for its uid mode's pathlab-confine), and
# the write-up in a browser (Chromium; tidy validates its HTML, poppler-utils reads its PDF),
# ccache, which serves the nested builds of the grading tests (quickstart.sh), and a YAML reader
# for the grading platforms' files (Autolab's assessment, GitHub Classroom's workflow), and strace, which
# lists every program a grade runs outside its sandbox (docs/threat-model.md); the formatter and the
# linter (clang-format, pyflakes: tools/check-format), and the web build's packages.
pathlab_test=(xvfb xauth libgl1-mesa-dri libglx-mesa0 imagemagick bubblewrap libseccomp-dev "${pathlab_writeup[@]}" tidy
              poppler-utils ccache python3-yaml strace clang-format pyflakes3
              "${pathlab_web[@]}")
# Grading: the core and the sandbox (bubblewrap; util-linux for setpriv, prlimit and ipcrm;
# libseccomp for pathlab-confine, the uid mode's system-call filter).
pathlab_grading=("${pathlab_core[@]}" bubblewrap util-linux libseccomp-dev)
# The hardening jobs: clang and its sanitizer and libFuzzer runtime.
pathlab_hardening=(clang libclang-rt-14-dev)
# Clang with libc++ (the macOS toolchain; preset clang-libcxx).
pathlab_libcxx=(clang libc++-14-dev libc++abi-14-dev)
# The aarch64 check (tools/aarch64-check): the cross compiler, qemu run through
# binfmt_misc, and mmdebstrap to make an arm64 root with the libraries below.
pathlab_aarch64=(cmake ninja-build pkg-config python3 g++-aarch64-linux-gnu qemu-user-static binfmt-support mmdebstrap)
# (No fast_float: there the OBJ reader's std::from_chars path is the one tested.)
pathlab_aarch64_root=(libc6-dev libstdc++-12-dev libglm-dev libopenimageio-dev doctest-dev nlohmann-json3-dev
                      libcli11-dev libpugixml-dev)
# Everything CI's stages use (.ci/run installs it first, timed as a stage of its own).
pathlab_ci=("${pathlab_build[@]}" "${pathlab_test[@]}" "${pathlab_hardening[@]}" "${pathlab_libcxx[@]}"
            "${pathlab_aarch64[@]}")
# Plots (make-report, the demos' figures).
pathlab_plots=(python3-matplotlib)

# install_packages PACKAGE...: apt-get installs the ones missing (sudo when not root).
install_packages() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  ((${#missing[@]} == 0)) && return 0
  local sudo=()
  [[ $(id -u) -ne 0 ]] && sudo=(sudo)
  echo "Installing: ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# missing_packages PACKAGE...: prints the ones not installed (nothing when all are).
missing_packages() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
