// boreas fuzzing: a tree species in boreas's JSON, parsed and then grown once
// (parse_species_json, grow_tree). The growth limits are smaller than the library's so that
// each input grows in milliseconds; the checks that enforce them are the library's own, so
// a species that slips past them here (a count not checked before it is grown) shows as a
// timeout or a memory finding whatever the limits.
#include "fuzz_input.h"
#include "trees/species.h"
#include "trees/tree_model.h"

namespace {

boreas::impl::GrowthLimits fuzz_limits() {
  boreas::impl::GrowthLimits limits;
  limits.branches = 4096;
  limits.leaves = 32768;
  limits.segments = 65536;
  return limits;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return boreas::fuzz::refused_or_read([&] {
    const boreas::impl::Species species =
        boreas::impl::parse_species_json(boreas::fuzz::text_of(data, size), "fuzz.json");
    (void)boreas::impl::grow_tree(species, 1, 1.0, fuzz_limits());
  });
}
