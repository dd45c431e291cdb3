// boreas tests and benchmarks: the kernels only they run (cl/fast_math_probe.cl,
// cl/bandwidth_copy.cl), which the installed library does not carry.
#pragma once

namespace boreas::impl {

// Makes every Runtime find the probe kernels by name; call before building one. Idempotent.
void use_probe_kernels();

}  // namespace boreas::impl
