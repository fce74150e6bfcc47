// A COLLADA file as an XML tree, with the reading every part of the loader
// needs: elements by id, numbers, indices, colours and float sources, each
// failing with one line that names the file and where. Private to the
// framework's sources: collada.cpp builds the scene from it.
#pragma once

#include <pugixml.hpp>

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/scene.h"
#include "util/math.h"

namespace pathlab::collada {

// Deeper XML is refused: COLLADA files nest about 10 levels, and reading
// nodes recurses once per level.
inline constexpr size_t kMaxXmlDepth = 256;

// One <source> of floats: `count` elements of `stride` numbers.
struct FloatSource {
  std::vector<float> values;
  size_t stride = 3;
  size_t count = 0;
};

class Document {
 public:
  // Reads and parses the file (a regular file within the size limit) and
  // indexes every element with an id.
  explicit Document(const std::string& path);

  const std::string& file() const { return file_; }
  pugi::xml_node root() const { return root_; }

  [[noreturn]] void fail(const std::string& where, const std::string& what) const;
  // The element a "#id" reference names.
  pugi::xml_node resolve(const std::string& url, const std::string& where) const;
  // The finite numbers of an element's text (exactly `expected` of them, if not 0).
  std::vector<float> numbers(pugi::xml_node node, const std::string& where, size_t expected = 0) const;
  // An integer attribute in [0, max] (a missing one is `fallback`).
  long integerAttribute(pugi::xml_node node, const char* name, long fallback, long max, const std::string& where) const;
  // The non-negative integers of an element's text.
  std::vector<long> indices(pugi::xml_node node, const std::string& where) const;
  // A colour of 3 or 4 non-negative numbers (alpha ignored).
  Color color(pugi::xml_node node, const std::string& where) const;
  // The float <source> `url` names, through a <vertices> element's POSITION input.
  FloatSource source(const std::string& url, const std::string& where) const;

  // The course's <extra><technique profile="CMU462"> (or "CGL") block.
  static pugi::xml_node courseTechnique(pugi::xml_node parent);

 private:
  void indexIds(pugi::xml_node root);

  std::string file_;
  pugi::xml_document document_;
  pugi::xml_node root_;
  std::map<std::string, pugi::xml_node> ids_;
};

// A colour or vector in messages: "(0.93 0.79 0.40)".
std::string formatted(const Vec3& v);

// Told (effect, what) when a material is only approximated (the loader
// reports the first, and how many more, in one warning line).
using ApproximationNote = std::function<void(const std::string& effect, const std::string& what)>;

// The material a <material> element describes, through its effect
// (collada_materials.cpp).
Material readMaterial(const Document& doc, pugi::xml_node material, const ApproximationNote& noteApproximation);

}  // namespace pathlab::collada
