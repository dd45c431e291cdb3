// boreas: Arbaro's species XML — <arbaro><species name='..'><param name='..' value='..'/>
// — read with pugixml and checked against the parameter table (species.cpp).
//
// Line numbers come from the byte offset pugixml keeps for every node (offset_debug) and
// for a syntax error (xml_parse_result::offset): the text is parsed as given, without
// encoding conversion, so an offset is a position in `text` and the line is one plus the
// newlines before it.
#include <algorithm>
#include <pugixml.hpp>
#include <string>

#include "errors.h"
#include "trees/species.h"

namespace boreas::impl {

namespace {

int line_at(const std::string& text, std::ptrdiff_t offset) {
  if (offset < 0) return 1;
  size_t end = std::min(static_cast<size_t>(offset), text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + end, '\n'));
}

// A node's line: where its first character other than white space is (text nodes keep the
// line break that precedes them).
int node_line(const std::string& text, const pugi::xml_node& node) {
  std::ptrdiff_t offset = node.offset_debug();
  if (offset < 0) return 1;
  size_t first = text.find_first_not_of(" \t\r\n", static_cast<size_t>(offset));
  return line_at(text, first == std::string::npos ? offset : static_cast<std::ptrdiff_t>(first));
}

std::string element_text(const pugi::xml_node& node) {
  return "<" + std::string(node.name()) + ">";
}

}  // namespace

Species parse_arbaro_xml(const std::string& text, const std::string& file_name) {
  SpeciesBuilder b(file_name);
  auto line_of = [&](const pugi::xml_node& node) { return node_line(text, node); };

  pugi::xml_document doc;
  pugi::xml_parse_result parsed =
      doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed) {
    b.fail_at(line_at(text, parsed.offset), std::string("malformed XML: ") + parsed.description());
  }

  pugi::xml_node root = doc.document_element();
  if (!root) b.fail_at(1, "no root element (expected <arbaro>)");
  for (pugi::xml_node second = root.next_sibling(); second; second = second.next_sibling()) {
    if (second.type() == pugi::node_element) {
      b.fail_at(line_of(second),
                "a second root element " + element_text(second) + " after <" + root.name() + ">");
    }
  }
  if (std::string(root.name()) != "arbaro") {
    b.fail_at(line_of(root), "root element is " + element_text(root) +
                                 ", expected <arbaro> (an Arbaro species file)");
  }

  pugi::xml_node species;
  for (pugi::xml_node child : root.children()) {
    if (child.type() != pugi::node_element || std::string(child.name()) != "species") {
      b.fail_at(line_of(child), "unexpected " +
                                    (child.type() == pugi::node_element ? element_text(child)
                                                                        : std::string("text")) +
                                    " in <arbaro>: expected one <species>");
    }
    if (species) {
      b.fail_at(line_of(child), "a second <species> (first on line " +
                                    std::to_string(line_of(species)) +
                                    "): an Arbaro file holds one species");
    }
    species = child;
  }
  if (!species) b.fail_at(line_of(root), "<arbaro> holds no <species>");

  pugi::xml_attribute name = species.attribute("name");
  if (!name || std::string(name.value()).empty()) {
    b.fail_at(line_of(species), "<species> has no name attribute");
  }
  b.set_name(name.value());

  for (pugi::xml_node param : species.children()) {
    int line = line_of(param);
    if (param.type() != pugi::node_element || std::string(param.name()) != "param") {
      b.fail_at(line, "unexpected " +
                          (param.type() == pugi::node_element ? element_text(param)
                                                              : std::string("text")) +
                          " in <species>: expected <param name='..' value='..'/>");
    }
    pugi::xml_attribute key = param.attribute("name");
    if (!key) b.fail_at(line, "<param> has no name attribute");
    pugi::xml_attribute value = param.attribute("value");
    if (!value) b.fail_param(line, key.value(), "<param> has no value attribute");
    for (pugi::xml_attribute a : param.attributes()) {
      std::string n = a.name();
      if (n != "name" && n != "value") {
        b.fail_param(line, key.value(), "unexpected attribute '" + n + "' on <param>");
      }
    }
    if (param.first_child()) b.fail_param(line, key.value(), "<param> must be empty");
    b.set_text(b.find(key.value(), line), value.value(), line);
  }
  return b.finish();
}

}  // namespace boreas::impl
