#include "engine/loading/yaml_fields.h"

namespace scenario {

Literal read_literal(const YAML::Node& n, const std::string& file, std::string_view what) {
  const auto s = read_string(n, file, what);
  Literal l;
  l.mark = mark_of(n, file);
  l.text = s;
  if (n.Tag() == "!") {  // quoted: always text
    l.kind = Literal::Kind::Text;
    return l;
  }
  if (auto i = parse_integer(s)) {
    l.kind = Literal::Kind::Integer;
    l.integer = *i;
  } else if (auto d = parse_number(s)) {
    l.kind = Literal::Kind::Real;
    l.real = *d;
  } else {
    l.kind = Literal::Kind::Text;
  }
  return l;
}

std::string Literal::to_string() const { return text; }

}  // namespace scenario
