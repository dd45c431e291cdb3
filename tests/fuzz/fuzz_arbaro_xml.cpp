// boreas fuzzing: a tree species in Arbaro's XML (parse_arbaro_xml).
#include "fuzz_input.h"
#include "trees/species.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return boreas::fuzz::refused_or_read(
      [&] { (void)boreas::impl::parse_arbaro_xml(boreas::fuzz::text_of(data, size), "fuzz.xml"); });
}
