// host tests: the C++ API (boreas.hpp, boreas_cl.hpp) covers every call of the C API
// (boreas.h, boreas_cl.h) under the same name, and adds no call of its own, so the two
// lists cannot drift. Read from the headers' text: the names are the contract.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

std::string read(const std::string& name) {
  std::ifstream in(std::string(BOREAS_INCLUDE_DIR) + "/boreas/" + name);
  EXPECT_TRUE(in.good()) << name;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The functions a C header exports.
std::set<std::string> c_calls(const std::string& header) {
  static const std::regex call(R"(BOREAS_API\s+[^;(]*?\b(boreas_\w+)\s*\()");
  std::set<std::string> out;
  const std::string text = read(header);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), call); it != std::sregex_iterator();
       ++it)
    out.insert((*it)[1]);
  return out;
}

// boreas.hpp without its namespace detail (the wrappers' own helpers).
std::string without_detail(std::string hpp) {
  const size_t begin = hpp.find("\nnamespace detail {");
  const size_t end = hpp.find("}  // namespace detail", begin);
  if (begin != std::string::npos && end != std::string::npos) hpp.erase(begin, end - begin);
  return hpp;
}

// The public part of boreas.hpp's World: from `class World {` to ` private:`.
std::string world_class(const std::string& hpp) {
  const size_t begin = hpp.find("\nclass World {");
  const size_t end = hpp.find("\n private:", begin);
  EXPECT_NE(begin, std::string::npos);
  return hpp.substr(begin, end - begin);
}

// The names of the functions a C++ text declares at the given indentation (members of a
// class: 2 spaces; free functions: none).
std::set<std::string> declared(const std::string& text, const std::string& indent) {
  const std::regex decl(
      "\n" + indent +
      R"((?:\[\[nodiscard\]\]\s+)?(?:inline\s+)?[\w:][\w:<>,\*& ]*?[\s\*&](\w+)\()");
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), decl); it != std::sregex_iterator();
       ++it)
    out.insert((*it)[1]);
  return out;
}

// The C++ name of a C call: without boreas_, and without world_ for the world's own.
std::string cpp_name(const std::string& c) {
  std::string name = c.substr(std::string("boreas_").size());
  if (name.rfind("world_", 0) == 0) name = name.substr(std::string("world_").size());
  return name;
}

// C calls whose C++ form is not a function of the same name, and why.
const std::set<std::string> kNotNamesakes = {
    "boreas_world_create",   // boreas::World's constructor
    "boreas_world_destroy",  // its destructor
    "boreas_last_error",     // boreas::Error's message (what())
};

TEST(ApiSurface, EveryCCallHasItsNamesakeInCpp) {
  const std::string hpp = without_detail(read("boreas.hpp")), cl_hpp = read("boreas_cl.hpp");
  const std::string world = world_class(hpp);
  const std::set<std::string> members = declared(world, "  ");
  std::string free_text = hpp;
  free_text.erase(hpp.find(world), world.size());
  const std::set<std::string> free = declared(free_text, ""), cl_free = declared(cl_hpp, "");
  const std::string c_header = read("boreas.h");
  int checked = 0;
  for (const std::string& c : c_calls("boreas.h")) {
    if (kNotNamesakes.count(c)) continue;
    // A call on a world takes it first: a member of World; the rest are free functions.
    const bool on_world =
        std::regex_search(c_header, std::regex("\\b" + c + R"(\(\s*boreas_world\s+world\b)"));
    const std::set<std::string>& where = on_world ? members : free;
    EXPECT_TRUE(where.count(cpp_name(c)))
        << c << " has no " << (on_world ? "boreas::World::" : "boreas::") << cpp_name(c);
    ++checked;
  }
  for (const std::string& c : c_calls("boreas_cl.h")) {
    EXPECT_TRUE(cl_free.count(cpp_name(c)))
        << c << " has no boreas::" << cpp_name(c) << " in boreas_cl.hpp";
    ++checked;
  }
  EXPECT_GT(checked, 60) << "the C headers' calls were not found";
}

TEST(ApiSurface, CppAddsNoCallOfItsOwn) {
  std::set<std::string> namesakes;
  for (const char* header : {"boreas.h", "boreas_cl.h"})
    for (const std::string& c : c_calls(header)) namesakes.insert(cpp_name(c));
  const std::string hpp = without_detail(read("boreas.hpp"));
  const std::string world = world_class(hpp);
  std::string free_text = hpp;
  free_text.erase(hpp.find(world), world.size());
  // The C++ layer's own plumbing: the constructor, the handle for C code, the status check.
  const std::set<std::string> plumbing = {"World", "handle", "check"};
  for (const std::string& text : {world, free_text, read("boreas_cl.hpp")})
    for (const std::string& name : declared(text, text == world ? "  " : ""))
      EXPECT_TRUE(namesakes.count(name) || plumbing.count(name))
          << name << " is not the name of a C call: name it as boreas.h does";
}

}  // namespace
