#!/usr/bin/env bash
# The whole test suite of hycon: the README's test command, also what CI runs (.ci/run).
#
#   scripts/test-all.sh
#
# Needs the Rust toolchain (with clippy and rustfmt) and gcc/g++. On Debian it first installs
# what else it needs (cmake, ninja-build, libsuitesparse-dev, libclang-dev, pkg-config,
# valgrind, g++, petsc-dev and openmpi-bin for the PETSc example, libfclib-dev for the FCLIB
# round trip) with apt-get when any is missing: as root, or through sudo.
# Order: tests first (their summaries are printed as they finish), then the static checks
# (clippy, rustfmt, rustdoc). Every step shares cargo's target/ directory. hycon is compiled
# four times, each for what only it can check: dev with CHOLMOD for every Rust test (one
# build: the backends test runs in it), release without features for CMake (what a host
# links: ctest, install, consumers), release with CHOLMOD for the C examples on CHOLMOD, and
# clippy's check build. No `cargo test --release`: its dev-dependencies change features of
# faer's dependencies, so faer would be compiled twice in release.
# The step timings printed at the end are kept in docs/ci-timings.md.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$PWD

start=$SECONDS
timings=()
current=""
step() {
    if [[ -n $current ]]; then timings+=("$(printf '%5d s  %s' $((SECONDS - step_start)) "$current")"); fi
    current="$*"
    step_start=$SECONDS
    printf '\n==== [%d s] %s\n' $((SECONDS - start)) "$current"
}
summary() {
    local rc=$?
    if [[ -n $current ]]; then timings+=("$(printf '%5d s  %s' $((SECONDS - step_start)) "$current")"); fi
    printf '\n==== step timings\n'
    printf '%s\n' "${timings[@]}"
    if ((rc == 0)); then
        printf '==== test-all: PASSED in %d s\n' $((SECONDS - start))
    else
        printf '==== test-all: FAILED (exit %d) in step "%s" after %d s\n' "$rc" "$current" $((SECONDS - start))
    fi
}
trap summary EXIT

packages=(cmake ninja-build libsuitesparse-dev libmetis5 libclang-dev pkg-config valgrind g++ petsc-dev openmpi-bin libfclib-dev)
missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
        missing+=("$p")
    fi
done
if ((${#missing[@]} > 0)); then
    step "install system packages: ${missing[*]}"
    sudo=()
    if [[ $(id -u) -ne 0 ]]; then sudo=(sudo); fi
    "${sudo[@]}" apt-get update
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get -o DPkg::Lock::Timeout=900 install -y "${packages[@]}"
else
    step "install system packages: none missing"
fi

export CARGO_TERM_COLOR=${CARGO_TERM_COLOR:-never}
# A full run gains nothing from incremental compilation, which costs CPU on a build from scratch:
# the workspace crates' test build took 237 s of CPU without it against 254 s with it (0.11.0,
# `cargo nextest run --no-run` after `cargo clean -p hycon -p hycon-lab`, /usr/bin/time).
export CARGO_INCREMENTAL=${CARGO_INCREMENTAL:-0}
build=$root/build
stage=$build/stage

# cargo-nextest (on the machines CI uses) runs the tests of every binary side by side, each in
# its own process; plain `cargo test` (binaries one after another) where it is not installed.
# Neither runs doctests: the crates have none (a ```rust block in a doc comment would need
# `cargo test --doc` here).
features=(--workspace --features hycon-lab/suitesparse,hycon-lab/fclib)
if cargo nextest --version >/dev/null 2>&1; then
    step "cargo nextest run ${features[*]} (unit, integration, C API, header, layout, faer against CHOLMOD, accuracy guard)"
    cargo nextest run --locked "${features[@]}" --no-fail-fast
else
    step "cargo test ${features[*]} (unit, integration, C API, header, layout, faer against CHOLMOD, accuracy guard)"
    log=$(mktemp)
    cargo test --locked "${features[@]}" 2>&1 | tee "$log"
    grep -E '^test result:' "$log" |
        awk '{p += $4; f += $6; i += $8} END {printf "==== cargo test: %d passed, %d failed, %d ignored\n", p, f, i}'
    rm -f "$log"
fi

step "cmake configure"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$stage" -DHYCON_REQUIRE_PETSC=ON

step "cmake build"
cmake --build "$build"

step "ctest (C/C++ examples shared + static, valgrind, ASan+UBSan)"
ctest --test-dir "$build" --output-on-failure -j2

step "cmake install"
rm -rf "$stage"
cmake --install "$build"

step "consumer project against the installed package (find_package + pkg-config)"
rm -rf "$build/consumer"
cmake -S tests/consumer -B "$build/consumer" -G Ninja -DCMAKE_PREFIX_PATH="$stage"
cmake --build "$build/consumer"
ctest --test-dir "$build/consumer" --output-on-failure

step "relocated install: consumer and plain pkg-config against a moved copy"
rm -rf "$build/relocated" "$build/consumer-relocated"
cp -a "$stage" "$build/relocated"
cmake -S tests/consumer -B "$build/consumer-relocated" -G Ninja -DCMAKE_PREFIX_PATH="$build/relocated"
cmake --build "$build/consumer-relocated"
ctest --test-dir "$build/consumer-relocated" --output-on-failure
PKG_CONFIG_PATH="$build/relocated/lib/pkgconfig" pkg-config --modversion hycon
# shellcheck disable=SC2046 # word splitting of pkg-config output is intended
cc -std=c99 -Wall -Wextra -Werror -pedantic tests/consumer/main.c -o "$build/consumer-pc" \
    $(PKG_CONFIG_PATH="$build/relocated/lib/pkgconfig" pkg-config --cflags --libs hycon)
LD_LIBRARY_PATH="$build/relocated/lib" "$build/consumer-pc"

step "cargo clippy --workspace --all-targets --all-features -- -D warnings"
cargo clippy --locked --workspace --all-targets --all-features -- -D warnings

step "cargo fmt --check"
cargo fmt --check

step "cargo doc --no-deps"
# With all features, as clippy: rustdoc then reuses clippy's check build of the dependencies (the
# lab's manifest gives bitflags the feature proptest gives it there), docs/ci-timings.md.
RUSTDOCFLAGS="-D warnings" cargo doc --locked --no-deps --all-features

# Last, because it rebuilds target/release/libhycon.* with the feature (the install and the
# consumers above used the default build).
step "CMake with -DHYCON_CARGO_FEATURES=suitesparse: the C examples on CHOLMOD (hertz_model_cholmod)"
cmake -S . -B "$build-suitesparse" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHYCON_CARGO_FEATURES=suitesparse \
    -DHYCON_SANITIZERS=OFF -DHYCON_VALGRIND=OFF
cmake --build "$build-suitesparse" --target hycon_cargo hertz_model cholmod_host
ctest --test-dir "$build-suitesparse" --output-on-failure -R '^(hertz_model|hertz_model_cholmod|cholmod_host)$'
