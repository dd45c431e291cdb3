// boreas fuzzing: an underbrush species file (parse_component_species).
#include "fuzz_input.h"
#include "underbrush/component_species.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return boreas::fuzz::refused_or_read([&] {
    (void)boreas::impl::parse_component_species(boreas::fuzz::text_of(data, size), "fuzz.json");
  });
}
