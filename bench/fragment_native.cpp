// The fragment benchmarks of kutlog's scalar eval(t), compiled with -march=native
// (bench/CMakeLists.txt), named /flags:native.
#include "fragment_benchmarks.hpp"

namespace kutlog::bench {

void register_native_fragment_benchmarks() { register_fragment_benchmarks("native"); }

}  // namespace kutlog::bench
