# Shared by scripts/test, scripts/demo and scripts/bench: install what is missing, then configure and build.
# Debian 12's own ROS 1 packages live in /usr: nothing to source before the build.
set -euo pipefail

# ROS tools need Debian's python3 (catkin_pkg, rospy), not a pyenv one that may come first on PATH.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:${PATH}"

REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-${REPO_ROOT}/build}"
# The install space scripts/test_install makes and removes: outside the repository, which is the package's own
# directory (roslaunch and rosrun search it whole, and would find a second copy of every launch file in it), and one
# per build directory.
INSTALL_PREFIX="${INSTALL_PREFIX:-${TMPDIR:-/tmp}/billiard_shot_planner-install-$(printf '%s' "$BUILD_DIR" | md5sum | cut -c1-8)}"

# The Debian packages there is no rosdep for on these machines: what the build and the demo need, then what the
# tests, benchmarks, fuzzing and checks need besides (docs/development.md lists each with its use).
DEMO_PACKAGES=(
  build-essential cmake
  catkin ros-core-dev python3-catkin-pkg rosbash
  libroscpp-dev libactionlib-dev libactionlib-msgs-dev python3-actionlib libtf2-ros-dev libmessage-filters-dev libtf2-geometry-msgs-dev libtf2-eigen-dev libvisualization-msgs-dev
  libinteractive-markers-dev
  libgeometry-msgs-dev libstd-srvs-dev python3-std-srvs python3-rospy tf2-tools
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  libdiagnostic-updater-dev python3-diagnostic-msgs
  libeigen3-dev libboost-dev nlohmann-json3-dev libyaml-cpp-dev libnlopt-cxx-dev libceres-dev
  pybind11-dev python3-numpy
  rviz xvfb xauth libgl1-mesa-dri imagemagick
)
TEST_PACKAGES=(
  librostest-dev python3-rostest python3-rosbag python3-tf2-ros python3-visualization-msgs
  libgtest-dev libbenchmark-dev python3-pil python3-pytest python3-yaml python3-distributed
  clang-format clang-tidy catkin-lint
  clang libclang-rt-14-dev
)
PACKAGES=("${DEMO_PACKAGES[@]}" "${TEST_PACKAGES[@]}")

# Each heading says how long the whole run (scripts/test and the scripts it calls) has taken so far.
BSP_STARTED="${BSP_STARTED:-$(date +%s)}"
export BSP_STARTED
log() { printf '\n\033[1m== %s\033[0m (%d s)\n' "$*" "$(($(date +%s) - BSP_STARTED))"; }

# install_packages [package...]: those missing of the given ones (default: every package).
install_packages() {
  local wanted=("$@")
  ((${#wanted[@]} > 0)) || wanted=("${PACKAGES[@]}")
  local missing=()
  for pkg in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  if ((${#missing[@]} == 0)); then
    log "Debian packages: all present"
    return
  fi
  log "Installing ${missing[*]}"
  local sudo=""
  [[ $(id -u) -eq 0 ]] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# configure_and_build [extra cmake args...]
configure_and_build() {
  log "Configuring in ${BUILD_DIR}"
  # catkin's cached test environment puts the devel space's Python path on PYTHONPATH only if it exists at
  # configure time; on a fresh clone the generated message modules land there after the first build.
  mkdir -p "${BUILD_DIR}/devel/lib/python3/dist-packages"
  # Tests on unless a caller (the demo) turns them off: the setting persists in the build directory's cache.
  cmake -S "$REPO_ROOT" -B "$BUILD_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$INSTALL_PREFIX" -DCATKIN_ENABLE_TESTING=ON "$@" >/dev/null
  log "Building"
  make -C "$BUILD_DIR" -j"$(nproc)" --no-print-directory
}

# The sanitized build that scripts/sanitize and scripts/fuzz share, so that its libraries are compiled once: clang,
# AddressSanitizer and UndefinedBehaviorSanitizer (-fno-sanitize-recover: any UB aborts), libFuzzer's coverage
# instrumentation, optimised with line tables (-O2 -g1: all a report's stack needs). NDEBUG stays off: Eigen's
# bounds and size checks fire too.
SANITIZED_BUILD_DIR="${SANITIZED_BUILD_DIR:-${REPO_ROOT}/build-asan}"
SANITIZE_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
configure_sanitized_build() {
  log "Configuring in ${SANITIZED_BUILD_DIR} (clang, ASan, UBSan, libFuzzer's coverage)"
  # As in configure_and_build: the devel space's Python path must exist at configure time.
  mkdir -p "${SANITIZED_BUILD_DIR}/devel/lib/python3/dist-packages"
  CC=clang CXX=clang++ cmake -S "$REPO_ROOT" -B "$SANITIZED_BUILD_DIR" -DPYTHON_EXECUTABLE=/usr/bin/python3 \
    -DCMAKE_BUILD_TYPE=Sanitized -DCMAKE_CXX_FLAGS_SANITIZED="-O2 -g1" \
    -DCMAKE_CXX_FLAGS="${SANITIZE_FLAGS} -fsanitize=fuzzer-no-link" -DCMAKE_EXE_LINKER_FLAGS="$SANITIZE_FLAGS" \
    -DCMAKE_SHARED_LINKER_FLAGS="$SANITIZE_FLAGS" -DBILLIARD_SHOT_PLANNER_FUZZ=ON >/dev/null
}
