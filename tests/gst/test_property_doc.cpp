// docs/element.md's property table against the element's real GParamSpecs: every documented
// property exists with its type, range, default and flags, and every property of the element is
// documented. The code is the truth; the doc repeats it by hand, and this is what keeps them equal.
//
// The table, under "## Properties": | property | type, range | default | meaning |, a row per
// property or per pair (`inner-point-x`, `inner-point-y`). "type, range" is `uint 3–1024`,
// `double 0–10⁶`, `int −1…` (up to the type's maximum), `boolean`, `enum (below)` (its values in
// a paragraph "`name` values (GType `...`"), `enum `a`, `b``, `flags `a`, `b`` (the default: its
// flags' nicks, `a+b`), or `` `GstValueArray` of 4 ints`` (`` of `GstValueArray` of 4 ints``: an
// array of arrays of ints, as start-boxes); `, read-only` marks a property
// that cannot be set, `, controllable` one a GstController may drive (GST_PARAM_CONTROLLABLE).
// Every other one is writable and, as the section says, safe to change while playing.
#include <gst/gst.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct GstEnvironment : ::testing::Environment {
  void SetUp() override { gst_init(nullptr, nullptr); }
};
const auto* const kGstEnvironment = ::testing::AddGlobalTestEnvironment(new GstEnvironment);

struct DocRow {
  std::vector<std::string> names;
  std::string type_range, def, line;
};

std::string read_doc() {
  std::ifstream in(PROJTRACK_ELEMENT_DOC);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// A table row's cells; `\|` inside a cell is a literal bar.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += line[++i];
    } else if (line[i] == '|') {
      out.push_back(trim(cell));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return out;
}

// The words between backticks.
std::vector<std::string> quoted(const std::string& s) {
  std::vector<std::string> out;
  static const std::regex code("`([^`]*)`");
  for (std::sregex_iterator it(s.begin(), s.end(), code), end; it != end; ++it)
    out.push_back((*it)[1]);
  return out;
}

// The rows of the table under "## Properties".
std::vector<DocRow> property_rows(const std::string& doc) {
  std::istringstream in(doc.substr(doc.find("\n## Properties\n")));
  std::string line;
  while (std::getline(in, line) && line.rfind("| property |", 0) != 0) {
  }
  EXPECT_EQ(cells(line),
            (std::vector<std::string>{"property", "type, range", "default", "meaning"}))
      << "the property table's header changed: " << line;
  std::getline(in, line);  // |---|---|
  std::vector<DocRow> rows;
  while (std::getline(in, line) && line.rfind('|', 0) == 0) {
    const std::vector<std::string> c = cells(line);
    if (c.size() < 3) continue;
    rows.push_back({quoted(c[0]), c[1], c[2], line});
  }
  return rows;
}

// A number as the doc writes it: "−1" (a minus sign), "4.0", "10⁶".
double number(std::string s) {
  static const std::pair<std::string, std::string> kSpellings[] = {
      {"\u2212", "-"},     {"10\u2070", "1e0"}, {"10\u00b9", "1e1"}, {"10\u00b2", "1e2"},
      {"10\u00b3", "1e3"}, {"10\u2074", "1e4"}, {"10\u2075", "1e5"}, {"10\u2076", "1e6"},
      {"10\u2077", "1e7"}, {"10\u2078", "1e8"}, {"10\u2079", "1e9"}};
  for (const auto& [from, to] : kSpellings)
    for (std::size_t at; (at = s.find(from)) != std::string::npos;) s.replace(at, from.size(), to);
  std::size_t used = 0;
  const double v = std::stod(s, &used);
  EXPECT_EQ(used, s.size()) << "not a number: " << s;
  return v;
}

struct Range {
  double min, max;
  bool to_type_max;  // "a…": from a up to the type's maximum
};

// "3–1024" or "−1…" after the type word, up to ", read-only".
bool parse_range(const std::string& text, Range* range) {
  static const std::regex pattern("^(\\S+?)(\u2013(\\S+?)|\u2026)(,.*)?$");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return false;
  range->min = number(m[1]);
  range->to_type_max = !m[3].matched;
  range->max = range->to_type_max ? NAN : number(m[3]);
  return true;
}

// The numeric pspec's limits and default, as doubles.
struct Numeric {
  double min, max, def, type_max;
};

bool numeric(GParamSpec* p, Numeric* n) {
  if (G_IS_PARAM_SPEC_UINT(p)) {
    auto* u = G_PARAM_SPEC_UINT(p);
    *n = {double(u->minimum), double(u->maximum), double(u->default_value), double(G_MAXUINT)};
  } else if (G_IS_PARAM_SPEC_INT(p)) {
    auto* i = G_PARAM_SPEC_INT(p);
    *n = {double(i->minimum), double(i->maximum), double(i->default_value), double(G_MAXINT)};
  } else if (G_IS_PARAM_SPEC_DOUBLE(p)) {
    auto* d = G_PARAM_SPEC_DOUBLE(p);
    *n = {d->minimum, d->maximum, d->default_value, G_MAXDOUBLE};
  } else {
    return false;
  }
  return true;
}

std::set<std::string> enum_nicks(GParamSpec* p) {
  std::set<std::string> nicks;
  GEnumClass* e = G_PARAM_SPEC_ENUM(p)->enum_class;
  for (guint i = 0; i < e->n_values; ++i) nicks.insert(e->values[i].value_nick);
  return nicks;
}

// The values of an enum documented "(below)": the backticked words of its paragraph "`name` values
// (GType `Type`...", but for those two.
std::set<std::string> nicks_below(const std::string& doc, const std::string& name,
                                  const char* gtype) {
  const std::string start = "`" + name + "` values (GType `" + gtype + "`";
  const std::size_t at = doc.find(start);
  if (at == std::string::npos) return {};
  const std::vector<std::string> words = quoted(doc.substr(at, doc.find("\n\n", at) - at));
  return {words.begin() + 2, words.end()};
}

class PropertyDoc : public ::testing::Test {
 protected:
  void SetUp() override {
    element_ = gst_element_factory_make("projtrack", nullptr);
    ASSERT_NE(element_, nullptr) << "is GST_PLUGIN_PATH set to the build's gst folder?";
    guint n = 0;
    GParamSpec** all = g_object_class_list_properties(G_OBJECT_GET_CLASS(element_), &n);
    for (guint i = 0; i < n; ++i)
      if (all[i]->owner_type == G_OBJECT_TYPE(element_)) specs_[all[i]->name] = all[i];
    g_free(all);
    doc_ = read_doc();
    ASSERT_NE(doc_.find("\n## Properties\n"), std::string::npos) << PROJTRACK_ELEMENT_DOC;
    rows_ = property_rows(doc_);
  }
  void TearDown() override {
    if (element_) gst_object_unref(element_);
  }

  // One documented property against its pspec.
  void check(const DocRow& row, const std::string& name, GParamSpec* p) const;

  GstElement* element_ = nullptr;
  std::map<std::string, GParamSpec*> specs_;  // the element's own properties
  std::string doc_;
  std::vector<DocRow> rows_;
};

void PropertyDoc::check(const DocRow& row, const std::string& name, GParamSpec* p) const {
  const std::string& tr = row.type_range;
  const std::string type = tr.substr(0, tr.find_first_of(" ,"));
  const std::string rest = trim(tr.substr(type.size()));
  const bool read_only = tr.find("read-only") != std::string::npos;

  const std::map<std::string, GType> kTypes = {{"uint", G_TYPE_UINT},
                                               {"int", G_TYPE_INT},
                                               {"double", G_TYPE_DOUBLE},
                                               {"boolean", G_TYPE_BOOLEAN},
                                               {"`GstValueArray`", GST_TYPE_ARRAY}};
  const GType value_type = G_PARAM_SPEC_VALUE_TYPE(p);
  if (type == "enum") {
    ASSERT_TRUE(G_TYPE_IS_ENUM(value_type)) << "not an enum";
    const std::vector<std::string> listed = quoted(rest);
    const std::set<std::string> documented =
        listed.empty() ? nicks_below(doc_, name, g_type_name(value_type))
                       : std::set<std::string>(listed.begin(), listed.end());
    EXPECT_EQ(documented, enum_nicks(p))
        << "the enum's values (GType " << g_type_name(value_type) << ")";
    GEnumValue* def =
        g_enum_get_value(G_PARAM_SPEC_ENUM(p)->enum_class, G_PARAM_SPEC_ENUM(p)->default_value);
    EXPECT_EQ(row.def, "`" + std::string(def->value_nick) + "`") << "default";
  } else if (type == "flags") {
    ASSERT_TRUE(G_TYPE_IS_FLAGS(value_type)) << "not flags";
    std::set<std::string> nicks;
    GFlagsClass* f = G_PARAM_SPEC_FLAGS(p)->flags_class;
    for (guint i = 0; i < f->n_values; ++i) nicks.insert(f->values[i].value_nick);
    const std::vector<std::string> listed = quoted(rest);
    EXPECT_EQ(std::set<std::string>(listed.begin(), listed.end()), nicks) << "the flags' values";
    std::string def;  // the nicks of the default's flags, joined by '+' (as gst-launch-1.0 takes)
    for (guint i = 0; i < f->n_values; ++i)
      if (G_PARAM_SPEC_FLAGS(p)->default_value & f->values[i].value)
        def += (def.empty() ? "" : "+") + std::string(f->values[i].value_nick);
    EXPECT_EQ(row.def, "`" + def + "`") << "default";
  } else {
    ASSERT_TRUE(kTypes.count(type)) << "unknown type \"" << type << "\"";
    EXPECT_STREQ(g_type_name(value_type), g_type_name(kTypes.at(type))) << "type";
  }

  Numeric n;
  if (numeric(p, &n)) {
    Range r;
    ASSERT_TRUE(parse_range(rest, &r)) << "a number needs its range (a–b, or a…): \"" << tr << "\"";
    EXPECT_DOUBLE_EQ(r.min, n.min) << "minimum";
    EXPECT_DOUBLE_EQ(r.to_type_max ? n.type_max : r.max, n.max) << "maximum";
    EXPECT_DOUBLE_EQ(number(row.def), n.def) << "default";
  } else if (G_IS_PARAM_SPEC_BOOLEAN(p)) {
    EXPECT_EQ(row.def, G_PARAM_SPEC_BOOLEAN(p)->default_value ? "true" : "false") << "default";
  } else if (value_type == GST_TYPE_ARRAY) {
    gchar* def = gst_value_serialize(g_param_spec_get_default_value(p));
    std::string spaceless = def;
    g_free(def);
    spaceless.erase(std::remove(spaceless.begin(), spaceless.end(), ' '), spaceless.end());
    EXPECT_EQ(row.def, "`" + spaceless + "`") << "default";
    // An array of ints, or (documented "of `GstValueArray` of") of arrays of ints.
    GParamSpec* element = GST_PARAM_SPEC_ARRAY_LIST(p)->element_spec;
    if (tr.find("of `GstValueArray` of") != std::string::npos) {
      ASSERT_EQ(G_PARAM_SPEC_VALUE_TYPE(element), GST_TYPE_ARRAY) << "an array of arrays";
      element = GST_PARAM_SPEC_ARRAY_LIST(element)->element_spec;
    }
    EXPECT_EQ(G_PARAM_SPEC_VALUE_TYPE(element), G_TYPE_INT) << "an array of ints";
  }

  EXPECT_EQ((p->flags & GST_PARAM_CONTROLLABLE) != 0, tr.find("controllable") != std::string::npos)
      << "controllable when documented so";
  EXPECT_TRUE(p->flags & G_PARAM_READABLE) << "readable";
  EXPECT_EQ(!(p->flags & G_PARAM_WRITABLE), read_only) << "writable unless documented read-only";
  if (!read_only) {
    EXPECT_TRUE(p->flags & GST_PARAM_MUTABLE_PLAYING) << "safe to change while playing";
  }
}

TEST_F(PropertyDoc, EveryRowMatchesTheElement) {
  ASSERT_FALSE(rows_.empty());
  for (const DocRow& row : rows_) {
    ASSERT_FALSE(row.names.empty()) << row.line;
    for (const std::string& name : row.names) {
      SCOPED_TRACE("docs/element.md, property " + name + ": " + row.line);
      const auto it = specs_.find(name);
      ASSERT_NE(it, specs_.end()) << "the element has no property " << name;
      check(row, name, it->second);
    }
  }
}

TEST_F(PropertyDoc, EveryPropertyIsDocumentedOnce) {
  std::map<std::string, int> documented;
  for (const DocRow& row : rows_)
    for (const std::string& name : row.names) ++documented[name];
  for (const auto& [name, spec] : specs_)
    EXPECT_EQ(documented[name], 1) << name << " in docs/element.md's property table";
}

}  // namespace
