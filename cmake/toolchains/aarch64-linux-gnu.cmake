# 64-bit ARM (phones since ~2015): Debian's g++-aarch64-linux-gnu, run under
# qemu-aarch64. GCC contracts a*b+c into fmadd by default; add
# -ffp-contract=off to CMAKE_CXX_FLAGS for x86-64's rounding (make test-arm).
#   cmake -S . -B build-arm/aarch64 -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu.cmake
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(FRUSTUM_CROSS_TRIPLE aarch64-linux-gnu)
set(FRUSTUM_QEMU qemu-aarch64)
include(${CMAKE_CURRENT_LIST_DIR}/linux-gnu-cross.cmake)
