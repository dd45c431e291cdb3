// boreas fuzzing: a tree species in boreas's JSON (parse_species_json).
#include "fuzz_input.h"
#include "trees/species.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return boreas::fuzz::refused_or_read([&] {
    (void)boreas::impl::parse_species_json(boreas::fuzz::text_of(data, size), "fuzz.json");
  });
}
