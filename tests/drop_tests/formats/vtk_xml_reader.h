#pragma once
// A small XML reader for the tests of the VTK output (drop_tests/formats/vtk_writer.h): elements,
// attributes and text, enough to read back what touchdown writes as ParaView would see it
// (declarations and comments skipped; no entities, touchdown writes none).
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace touchdown::testing_vtk {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<XmlElement> children;

  // Copies of the children named `n`, in order (copies: safe to keep from a temporary document).
  std::vector<XmlElement> All(const std::string& n) const {
    std::vector<XmlElement> out;
    for (const XmlElement& c : children)
      if (c.name == n) out.push_back(c);
    return out;
  }
  XmlElement One(const std::string& n) const {
    std::vector<XmlElement> all = All(n);
    if (all.size() != 1) throw std::runtime_error("expected one <" + n + "> in <" + name + ">");
    return std::move(all.front());
  }
  const std::string& Attribute(const std::string& a) const {
    const auto it = attributes.find(a);
    if (it == attributes.end()) throw std::runtime_error("<" + name + "> has no attribute " + a);
    return it->second;
  }
  // The text as numbers (strtod: every double written with 17 digits reads back exactly).
  std::vector<double> Numbers() const {
    std::vector<double> out;
    const char* p = text.c_str();
    for (char* end = nullptr;; p = end) {
      const double v = std::strtod(p, &end);
      if (end == p) break;
      out.push_back(v);
    }
    return out;
  }
};

class XmlReader {
 public:
  explicit XmlReader(std::string text) : s_(std::move(text)) {}
  XmlElement Root() {
    SkipProlog();
    XmlElement root = Element();
    SkipSpace();
    if (i_ != s_.size()) throw std::runtime_error("text after the root element");
    return root;
  }

 private:
  void SkipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  void SkipProlog() {
    for (SkipSpace(); s_.compare(i_, 2, "<?") == 0 || s_.compare(i_, 4, "<!--") == 0; SkipSpace()) {
      const bool declaration = s_[i_ + 1] == '?';
      const size_t end = s_.find(declaration ? "?>" : "-->", i_);
      if (end == std::string::npos) throw std::runtime_error("unterminated prolog");
      i_ = end + (declaration ? 2 : 3);
    }
  }
  std::string Name() {
    const size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == ':'))
      ++i_;
    if (i_ == start) throw std::runtime_error("expected a name at offset " + std::to_string(i_));
    return s_.substr(start, i_ - start);
  }
  void Expect(char c) {
    if (i_ >= s_.size() || s_[i_] != c)
      throw std::runtime_error(std::string("expected '") + c + "' at offset " + std::to_string(i_));
    ++i_;
  }
  XmlElement Element() {
    XmlElement e;
    Expect('<');
    e.name = Name();
    for (SkipSpace(); i_ < s_.size() && s_[i_] != '>' && s_[i_] != '/'; SkipSpace()) {
      const std::string key = Name();
      Expect('=');
      Expect('"');
      const size_t end = s_.find('"', i_);
      if (end == std::string::npos) throw std::runtime_error("unterminated attribute " + key);
      if (!e.attributes.emplace(key, s_.substr(i_, end - i_)).second) throw std::runtime_error("repeated " + key);
      i_ = end + 1;
    }
    if (s_.compare(i_, 2, "/>") == 0) {
      i_ += 2;
      return e;
    }
    Expect('>');
    while (true) {
      const size_t lt = s_.find('<', i_);
      if (lt == std::string::npos) throw std::runtime_error("unterminated <" + e.name + ">");
      e.text += s_.substr(i_, lt - i_);
      i_ = lt;
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        if (Name() != e.name) throw std::runtime_error("mismatched </...> for <" + e.name + ">");
        Expect('>');
        return e;
      }
      e.children.push_back(Element());
    }
  }
  std::string s_;
  size_t i_ = 0;
};

inline XmlElement ReadXmlFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::stringstream s;
  s << in.rdbuf();
  return XmlReader(s.str()).Root();
}

// A .vtp's pieces (VTKFile > PolyData > Piece).
inline std::vector<XmlElement> VtpPieces(const XmlElement& root) {
  if (root.name != "VTKFile" || root.Attribute("type") != "PolyData") throw std::runtime_error("not a PolyData file");
  return root.One("PolyData").All("Piece");
}

// The DataArray named `name` under `parent` (CellData, PointData, Points, Polys, Lines).
inline XmlElement DataArray(const XmlElement& parent, const std::string& name) {
  for (const XmlElement& a : parent.children)
    if (a.name == "DataArray" && a.attributes.count("Name") && a.attributes.at("Name") == name) return a;
  throw std::runtime_error("no DataArray " + name + " in <" + parent.name + ">");
}

}  // namespace touchdown::testing_vtk
