#include "scene_file.hpp"

#include <fmt/format.h>

#include <toml++/toml.h>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "user_error.hpp"

namespace granshock {

namespace {

// Keys and values echoed in messages are cut to this length: one line, however long the
// input (a --set value may be megabytes).
constexpr std::size_t kEchoLength = 80;
std::string clip(const std::string& text) {
  std::string out = text.size() <= kEchoLength ? text : text.substr(0, kEchoLength) + "...";
  for (char& c : out)
    if (c == '\n' || c == '\r') c = ' ';
  return out;
}

[[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& what) {
  throw UserError(fmt::format("scene key '{}' = {}: {}", clip(key), clip(value), what));
}

// More blocks than this only divide the production window into noise (and memory).
constexpr long kMaxBlocks = 10000;

// A scene name names the run directory runs/<name>: it must be a plain file name.
bool is_safe_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.' || name[0] == '-') return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'))
      return false;
  return true;
}

std::string show(const toml::node& n) {
  std::ostringstream os;
  if (auto s = n.as_string())
    os << '"' << s->get() << '"';
  else if (n.is_table())
    os << "(a table)";
  else if (n.is_array())
    os << "(an array)";
  else
    n.visit([&](auto&& v) { os << v; });
  return os.str();
}

// Reads the keys of one TOML table and remembers which it knew, so that finish() can
// report the ones it did not.
class TableReader {
 public:
  TableReader(const toml::table* table, std::string path, double d_m)
      : table_(table), path_(std::move(path)), d_m_(d_m) {}

  std::string key(const std::string& name) const {
    return path_.empty() ? name : path_ + "." + name;
  }
  bool has(const std::string& name) {
    known_.insert(name);
    return table_ && table_->contains(name);
  }
  const toml::node* node(const std::string& name) {
    known_.insert(name);
    return table_ ? table_->get(name) : nullptr;
  }
  const toml::node& required(const std::string& name) {
    const toml::node* n = node(name);
    if (!n) fail(key(name), "(missing)", "this key is required");
    return *n;
  }

  double number(const std::string& name, std::optional<double> fallback = std::nullopt) {
    const toml::node* n = node(name);
    if (!n) {
      if (!fallback) fail(key(name), "(missing)", "this key is required (a number)");
      return *fallback;
    }
    const auto v = n->value<double>();
    if (!v || n->is_boolean()) fail(key(name), show(*n), "must be a number");
    if (!std::isfinite(*v)) fail(key(name), show(*n), "must be finite");
    return *v;
  }
  double number_in(const std::string& name, double lo, double hi, bool lo_open, bool hi_open,
                   std::optional<double> fallback = std::nullopt) {
    const double v = number(name, fallback);
    const bool ok = (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
    if (!ok)
      fail(key(name), fmt::format("{}", v),
           fmt::format("must be in {}{}, {}{}", lo_open ? "(" : "[", fmt_bound(lo), fmt_bound(hi),
                       hi_open ? ")" : "]"));
    return v;
  }
  double positive(const std::string& name, std::optional<double> fallback = std::nullopt) {
    const double v = number(name, fallback);
    if (!(v > 0)) fail(key(name), fmt::format("{}", v), "must be > 0");
    return v;
  }
  long integer_at_least(const std::string& name, long lo, long fallback) {
    const toml::node* n = node(name);
    if (!n) return fallback;
    const auto v = n->value<int64_t>();
    if (!n->is_integer() || !v) fail(key(name), show(*n), "must be an integer");
    if (*v < lo) fail(key(name), show(*n), fmt::format("must be >= {}", lo));
    return long(*v);
  }
  bool boolean(const std::string& name, bool fallback) {
    const toml::node* n = node(name);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(key(name), show(*n), "must be true or false");
    return *n->value<bool>();
  }
  std::string string(const std::string& name, std::optional<std::string> fallback = std::nullopt) {
    const toml::node* n = node(name);
    if (!n) {
      if (!fallback) fail(key(name), "(missing)", "this key is required (a string)");
      return *fallback;
    }
    if (!n->is_string()) fail(key(name), show(*n), "must be a string");
    return *n->value<std::string>();
  }
  std::string choice(const std::string& name, const std::vector<std::string>& options,
                     const std::string& fallback) {
    const std::string v = string(name, fallback);
    for (const auto& o : options)
      if (o == v) return v;
    fail(key(name), '"' + v + '"', fmt::format("must be one of {}", fmt::join(options, ", ")));
  }
  // A length: a number in metres, or a string "N d" (N particle diameters) or "N m".
  double length(const std::string& name, std::optional<double> fallback = std::nullopt) {
    const toml::node* n = node(name);
    if (!n) {
      if (!fallback) fail(key(name), "(missing)", "this key is required (a length)");
      return *fallback;
    }
    return length_of(*n, key(name));
  }
  double length_of(const toml::node& n, const std::string& k) const {
    if (auto v = n.value<double>(); v && !n.is_string() && !n.is_boolean()) return *v;
    if (n.is_string()) {
      std::istringstream in(*n.value<std::string>());
      double value = 0;
      std::string unit, rest;
      if (in >> value >> unit && !(in >> rest) && std::isfinite(value)) {
        if (unit == "d") return value * d_m_;
        if (unit == "m") return value;
      }
    }
    fail(k, show(n), "must be a length: a number in metres, or \"N d\" or \"N m\"");
  }
  double positive_length(const std::string& name, std::optional<double> fallback = std::nullopt) {
    const double v = length(name, fallback);
    if (!(v > 0)) fail(key(name), fmt::format("{} m", v), "must be > 0");
    return v;
  }
  const toml::table* table(const std::string& name) {
    const toml::node* n = node(name);
    if (!n) return nullptr;
    if (!n->is_table()) fail(key(name), show(*n), "must be a table");
    return n->as_table();
  }

  void finish() const {
    if (!table_) return;
    for (const auto& [k, v] : *table_) {
      const std::string name(k.str());
      if (!known_.count(name))
        fail(key(name), show(v),
             fmt::format("unknown key (accepted here: {})", fmt::join(known_, ", ")));
    }
  }

 private:
  static std::string fmt_bound(double b) {
    return std::isinf(b) ? (b > 0 ? "inf" : "-inf") : fmt::format("{}", b);
  }
  const toml::table* table_;
  std::string path_;
  double d_m_;
  std::set<std::string> known_;
};

// --set key=value: the value is read as TOML (so 0.5, true, "x", [1, 2] work) and taken
// as a plain string when it is not valid TOML (so 50 d works without quotes).
void apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw UserError(
        fmt::format("--set '{}': expected key=value (e.g. inflow.mach=13.7)", clip(assignment)));
  const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    parsed.insert_or_assign("v", text);
  }
  std::vector<std::string> parts;
  std::istringstream in(path);
  for (std::string p; std::getline(in, p, '.');) parts.push_back(p);
  toml::node* here = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (auto* t = here->as_table()) {
      if (!t->contains(parts[i])) t->insert(parts[i], toml::table{});
      here = t->get(parts[i]);
    } else if (auto* a = here->as_array()) {
      char* end = nullptr;
      const long index = std::strtol(parts[i].c_str(), &end, 10);
      if (*end || index < 0 || std::size_t(index) >= a->size())
        throw UserError(fmt::format("--set '{}': '{}' is not an index of this array (0..{})",
                                    clip(assignment), clip(parts[i]), a->size() - 1));
      here = a->get(std::size_t(index));
    } else {
      throw UserError(
          fmt::format("--set '{}': '{}' is not a table", clip(assignment), clip(parts[i])));
    }
  }
  auto* target = here->as_table();
  if (!target)
    throw UserError(fmt::format("--set '{}': the parent of '{}' is not a table", clip(assignment),
                                clip(parts.back())));
  target->insert_or_assign(parts.back(), *parsed.get("v"));
}

Material read_material(TableReader& r) {
  Material m;
  m.youngs_modulus_pa = r.positive("youngs_modulus");
  m.poisson_ratio = r.number_in("poisson_ratio", -1.0, 0.5, true, true);
  m.density_kg_m3 = r.positive("density");
  r.finish();
  return m;
}

}  // namespace

LoadedScene parse_scene(const std::string& text, const std::vector<std::string>& overrides,
                        const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: not valid TOML: {}", clip(origin), e.source().begin.line,
                                e.source().begin.column, clip(std::string(e.description()))));
  }
  for (const auto& o : overrides) apply_override(root, o);

  LoadedScene out;
  out.as_given = text;
  Scene& s = out.scene;
  TableReader top(&root, "", 1.0);

  {  // [units] first: lengths elsewhere may be written in d
    TableReader r(top.table("units"), "units", 1.0);
    s.d_m = r.positive("d", 1e-3);
    r.finish();
  }
  const double d = s.d_m;
  {
    TableReader r(top.table("scene"), "scene", d);
    s.name = r.string("name", "unnamed");
    if (!is_safe_name(s.name))
      fail("scene.name", '"' + s.name + '"',
           "must be 1 to 64 characters of A-Z a-z 0-9 . _ -, not starting with '.' or '-' (it "
           "names the run directory runs/<name>)");
    const long dim = r.integer_at_least("dim", 2, 2);
    if (dim != 2)
      fail("scene.dim", std::to_string(dim), "only quasi-2-D scenes (dim = 2) are supported");
    s.setup.dim = 2;
    s.run.seed = std::uint64_t(r.integer_at_least("seed", 0, 1));
    r.finish();
  }

  std::map<std::string, Material> materials = {{"steel", steel()}, {"aluminium", aluminium()}};
  if (const toml::table* mt = top.table("materials")) {
    for (const auto& [k, v] : *mt) {
      const std::string name(k.str());
      if (!v.is_table()) fail("materials." + name, show(v), "must be a table");
      TableReader r(v.as_table(), "materials." + name, d);
      materials[name] = read_material(r);
      materials[name].name = name;
    }
  }
  auto material_named = [&](const std::string& key, const std::string& name) {
    const auto it = materials.find(name);
    if (it == materials.end()) {
      std::vector<std::string> names;
      for (const auto& [n, m] : materials) names.push_back(n);
      fail(key, '"' + name + '"',
           fmt::format("unknown material (defined: {})", fmt::join(names, ", ")));
    }
    return it->second;
  };

  {
    const toml::node* sp = top.node("species");
    if (!sp || !sp->is_array_of_tables() || sp->as_array()->empty())
      fail("species", sp ? show(*sp) : "(missing)", "needs one or more [[species]] tables");
    double fraction_sum = 0;
    int index = 0;
    for (const auto& item : *sp->as_array()) {
      TableReader r(item.as_table(), fmt::format("species.{}", index++), d);
      Species species;
      species.name = r.string("name");
      for (const auto& other : s.setup.species)
        if (other.name == species.name)
          fail(r.key("name"), '"' + species.name + '"', "species names must be unique");
      species.material = material_named(r.key("material"), r.string("material"));
      species.diameter_m = r.positive_length("diameter");
      const double fraction = r.number_in("number_fraction", 0, 1, true, false);
      fraction_sum += fraction;
      s.inflow.number_fraction.push_back(fraction);
      s.setup.species.push_back(species);
      r.finish();
    }
    if (std::abs(fraction_sum - 1.0) > 1e-9)
      fail("species.*.number_fraction", fmt::format("sum {}", fraction_sum),
           "the number fractions must add up to 1");
  }
  const int n_species = int(s.setup.species.size());
  auto species_index = [&](const std::string& key, const std::string& name) {
    for (int a = 0; a < n_species; ++a)
      if (s.setup.species[a].name == name) return a;
    fail(key, '"' + name + '"', "unknown species");
  };

  std::optional<double> characteristic_velocity;  // default: the inflow speed
  {
    TableReader r(top.table("contact"), "contact", d);
    const double e = r.number_in("restitution", 0, 1, true, false);
    const double mu = r.number_in("friction", 0, INFINITY, false, true, 0.0);
    s.setup.contacts = ContactSettings::uniform(n_species, e, mu);
    s.setup.contacts.model = parse_contact_model(r.choice("model", {"hertz", "hooke"}, "hertz"));
    s.setup.contacts.options.limit_force = r.boolean("limit_force", false);
    if (r.has("characteristic_velocity"))
      characteristic_velocity = r.positive("characteristic_velocity");
    if (const toml::table* pairs = r.table("pairs")) {
      for (const auto& [k, v] : *pairs) {
        const std::string name(k.str()), key = "contact.pairs." + name;
        const auto dash = name.find('-');
        if (dash == std::string::npos || !v.is_table())
          fail(key, show(v), "must be a table named \"a-b\" or \"a-obstacle\" for species a, b");
        const int a = species_index(key, name.substr(0, dash));
        const std::string other = name.substr(dash + 1);
        TableReader pr(v.as_table(), key, d);
        if (other == "obstacle") {
          s.setup.contacts.obstacle_restitution[a] = pr.number_in(
              "restitution", 0, 1, true, false, s.setup.contacts.obstacle_restitution[a]);
          s.setup.contacts.obstacle_friction[a] = pr.number_in(
              "friction", 0, INFINITY, false, true, s.setup.contacts.obstacle_friction[a]);
        } else {
          const int b = species_index(key, other);
          const double pe =
              pr.number_in("restitution", 0, 1, true, false, s.setup.contacts.restitution[a][b]);
          const double pm =
              pr.number_in("friction", 0, INFINITY, false, true, s.setup.contacts.friction[a][b]);
          s.setup.contacts.restitution[a][b] = s.setup.contacts.restitution[b][a] = pe;
          s.setup.contacts.friction[a][b] = s.setup.contacts.friction[b][a] = pm;
        }
        pr.finish();
      }
    }
    r.finish();
  }

  {
    TableReader r(top.table("numerics"), "numerics", d);
    s.setup.precision = r.choice("precision", {"double", "single"}, "double") == "single"
                            ? Precision::single_precision
                            : Precision::double_precision;
    s.setup.skin_m = r.length("skin", 0.3 * s.setup.max_diameter());
    if (!(s.setup.skin_m > 0))
      fail("numerics.skin", fmt::format("{} m", s.setup.skin_m), "must be > 0");
    s.mass_definition = parse_mass_definition(
        r.choice("mass_definition", {"mixture_mean", "paper_sum"}, "mixture_mean"));
    s.bin_size_m = r.positive_length("bin_size", 3 * d);
    s.field_scatter = r.choice("field_scatter", {"atomic", "scatter_view"}, "atomic") == "atomic"
                          ? ScatterStrategy::atomic
                          : ScatterStrategy::scatter_view;
    r.finish();
  }

  {
    TableReader r(top.table("domain"), "domain", d);
    const double width = r.positive_length("width"), length = r.positive_length("length");
    const double range = s.setup.max_diameter() + s.setup.skin_m;
    if (width < 3 * range)
      fail("domain.width", fmt::format("{} m", width),
           fmt::format("must be at least 3 interaction ranges ({} m)", 3 * range));
    s.setup.box.lo = {0, 0, 0};
    s.setup.box.hi = {width, length, s.setup.max_diameter()};
    s.setup.box.periodic = {true, false, false};
    s.setup.delete_outside = true;
    r.finish();
  }
  const double width = s.setup.box.hi[0], length = s.setup.box.hi[1];

  {
    TableReader r(top.table("inflow"), "inflow", d);
    s.inflow.area_fraction = r.positive("area_fraction");
    if (s.inflow.area_fraction > kMaxInflowAreaFraction)
      fail("inflow.area_fraction", fmt::format("{}", s.inflow.area_fraction),
           fmt::format("must be in (0, {}]: random insertion in the strip reaches about 0.42 "
                       "(measured; random sequential adsorption of discs jams at 0.547, "
                       "Hinrichsen, Feder & Jossang 1986), so more cannot be met "
                       "(docs/scene_format.md)",
                       kMaxInflowAreaFraction));
    s.inflow.speed_m_per_s = r.positive("velocity");
    if (r.has("sigma") == r.has("mach"))
      fail("inflow.sigma / inflow.mach", "(both or neither)",
           "give exactly one: sigma (m/s) or mach");
    if (r.has("sigma")) s.inflow.sigma_m_per_s = r.number_in("sigma", 0, INFINITY, false, true);
    if (r.has("mach")) s.inflow.target_mach = r.positive("mach");
    s.inflow.mach_at =
        parse_mach_reference(r.choice("mach_at", {"inserted", "inlet_bins"}, "inserted"));
    if (s.inflow.mach_at == MachReference::inlet_bins && !s.inflow.target_mach)
      fail("inflow.mach_at", "\"inlet_bins\"",
           "needs inflow.mach, the Mach number to calibrate sigma for");
    s.inflow.strip_m = r.length("strip", 2 * d);
    if (s.inflow.strip_m < s.setup.max_diameter() || s.inflow.strip_m >= length)
      fail("inflow.strip", fmt::format("{} m", s.inflow.strip_m),
           "must be at least one diameter and shorter than the domain");
    r.finish();
  }

  if (const toml::table* ot = top.table("obstacle")) {
    TableReader r(ot, "obstacle", d);
    Obstacle c;
    c.diameter_m = r.positive_length("diameter");
    c.material = material_named("obstacle.material", r.string("material", "aluminium"));
    c.centre = {0.5 * width, 0.5 * length, 0};
    if (const toml::node* cn = r.node("centre")) {
      const toml::array* a = cn->as_array();
      if (!a || a->size() != 2) fail("obstacle.centre", show(*cn), "must be [x, y] (two lengths)");
      c.centre[0] = r.length_of(*a->get(0), "obstacle.centre[0]");
      c.centre[1] = r.length_of(*a->get(1), "obstacle.centre[1]");
    }
    const double radius = 0.5 * c.diameter_m;
    if (c.centre[0] - radius < 0 || c.centre[0] + radius > width ||
        c.centre[1] - radius < s.inflow.strip_m + s.setup.max_diameter() ||
        c.centre[1] + radius > length)
      fail("obstacle",
           fmt::format("centre ({}, {}) m, diameter {} m", c.centre[0], c.centre[1], c.diameter_m),
           "the cylinder must lie inside the domain, downstream of the insertion strip");
    s.setup.obstacle = c;
    r.finish();
  }

  {
    TableReader r(top.table("time"), "time", d);
    s.setup.dt = r.positive("dt");
    s.run.duration_s = r.positive("duration");
    s.run.production_start_s =
        r.number_in("production_start", 0, s.run.duration_s, false, true, 0.5 * s.run.duration_s);
    r.finish();
  }
  {
    TableReader r(top.table("output"), "output", d);
    s.run.snapshot_interval_s = r.positive("snapshot_interval", s.run.duration_s / 10);
    s.run.series_interval_s = r.positive("series_interval", s.run.duration_s / 200);
    s.run.checkpoint_interval_s = r.positive("checkpoint_interval", s.run.duration_s / 5);
    s.run.progress_interval_s = r.positive("progress_interval", 2.0);
    s.run.sample_every = r.integer_at_least("sample_every", 1, 100);
    const long blocks = r.integer_at_least("blocks", 2, 10);
    if (blocks > kMaxBlocks)
      fail("output.blocks", std::to_string(blocks),
           fmt::format("must be at most {} (each block keeps its own bin sums)", kMaxBlocks));
    s.run.blocks = int(blocks);
    r.finish();
  }
  top.finish();

  s.setup.contacts.options.characteristic_velocity_m_per_s =
      characteristic_velocity.value_or(s.inflow.speed_m_per_s);
  resolve_inflow(s);
  out.resolved = scene_to_toml(s);
  return out;
}

namespace {
void collect_differences(const toml::node* a, const toml::node* b, const std::string& key,
                         std::set<std::string>& out) {
  const toml::table* ta = a ? a->as_table() : nullptr;
  const toml::table* tb = b ? b->as_table() : nullptr;
  if (ta && tb) {
    std::set<std::string> names;
    for (const auto& [k, v] : *ta) names.insert(std::string(k.str()));
    for (const auto& [k, v] : *tb) names.insert(std::string(k.str()));
    for (const auto& name : names)
      collect_differences(ta->get(name), tb->get(name), key.empty() ? name : key + "." + name, out);
    return;
  }
  const toml::array* aa = a ? a->as_array() : nullptr;
  const toml::array* ab = b ? b->as_array() : nullptr;
  if (aa && ab && aa->size() == ab->size()) {
    for (std::size_t i = 0; i < aa->size(); ++i)
      collect_differences(aa->get(i), ab->get(i), key + "." + std::to_string(i), out);
    return;
  }
  if (toml::node_view<const toml::node>{a} != toml::node_view<const toml::node>{b}) out.insert(key);
}
}  // namespace

std::vector<std::string> differing_keys(const std::string& toml_a, const std::string& toml_b) {
  toml::table a, b;
  try {
    a = toml::parse(toml_a);
    b = toml::parse(toml_b);
  } catch (const toml::parse_error&) {
    return {"(the scene text)"};
  }
  std::set<std::string> keys;
  collect_differences(&a, &b, "", keys);
  return {keys.begin(), keys.end()};
}

LoadedScene load_scene_file(const std::filesystem::path& path,
                            const std::vector<std::string>& overrides) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status))
    throw UserError(fmt::format("cannot read scene file '{}': no such file", clip(path.string())));
  if (fs::is_directory(status))
    throw UserError(
        fmt::format("scene file '{}' is a directory, not a TOML file", clip(path.string())));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw UserError(
        fmt::format("cannot read scene file '{}': {}", clip(path.string()), std::strerror(errno)));
  // Bounded read: a scene is a short text, and /dev/zero or a huge file must not hang us.
  std::string text(kMaxSceneFileBytes + 1, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));
  if (text.size() > kMaxSceneFileBytes)
    throw UserError(
        fmt::format("scene file '{}' is longer than {} bytes; a scene is a short "
                    "TOML text",
                    clip(path.string()), kMaxSceneFileBytes));
  return parse_scene(text, overrides, path.string());
}

std::string scene_to_toml(const Scene& s) {
  toml::table root;
  root.insert("scene",
              toml::table{{"name", s.name}, {"dim", s.setup.dim}, {"seed", int64_t(s.run.seed)}});
  root.insert("units", toml::table{{"d", s.d_m}});
  toml::table materials;
  toml::array species;
  for (std::size_t a = 0; a < s.setup.species.size(); ++a) {
    const Species& sp = s.setup.species[a];
    const std::string mat = "species_" + sp.name;
    materials.insert(mat, toml::table{{"youngs_modulus", sp.material.youngs_modulus_pa},
                                      {"poisson_ratio", sp.material.poisson_ratio},
                                      {"density", sp.material.density_kg_m3}});
    species.push_back(toml::table{{"name", sp.name},
                                  {"material", mat},
                                  {"diameter", sp.diameter_m},
                                  {"number_fraction", s.inflow.number_fraction[a]}});
  }
  toml::table contact{
      {"model", to_string(s.setup.contacts.model)},
      {"restitution", s.setup.contacts.restitution[0][0]},
      {"friction", s.setup.contacts.friction[0][0]},
      {"limit_force", s.setup.contacts.options.limit_force},
      {"characteristic_velocity", s.setup.contacts.options.characteristic_velocity_m_per_s}};
  toml::table pairs;
  for (std::size_t a = 0; a < s.setup.species.size(); ++a) {
    for (std::size_t b = a; b < s.setup.species.size(); ++b)
      pairs.insert(s.setup.species[a].name + "-" + s.setup.species[b].name,
                   toml::table{{"restitution", s.setup.contacts.restitution[a][b]},
                               {"friction", s.setup.contacts.friction[a][b]}});
    pairs.insert(s.setup.species[a].name + "-obstacle",
                 toml::table{{"restitution", s.setup.contacts.obstacle_restitution[a]},
                             {"friction", s.setup.contacts.obstacle_friction[a]}});
  }
  contact.insert("pairs", pairs);
  if (s.setup.obstacle) {
    const auto& c = *s.setup.obstacle;
    materials.insert("obstacle", toml::table{{"youngs_modulus", c.material.youngs_modulus_pa},
                                             {"poisson_ratio", c.material.poisson_ratio},
                                             {"density", c.material.density_kg_m3}});
    root.insert("obstacle", toml::table{{"diameter", c.diameter_m},
                                        {"material", "obstacle"},
                                        {"centre", toml::array{c.centre[0], c.centre[1]}}});
  }
  root.insert("materials", materials);
  root.insert("species", species);
  root.insert("contact", contact);
  root.insert("domain", toml::table{{"width", s.setup.box.hi[0]}, {"length", s.setup.box.hi[1]}});
  toml::table inflow{{"area_fraction", s.inflow.area_fraction},
                     {"velocity", s.inflow.speed_m_per_s},
                     {"sigma", s.inflow.sigma},
                     {"strip", s.inflow.strip_m}};
  root.insert("inflow", inflow);
  root.insert("time", toml::table{{"dt", s.setup.dt},
                                  {"duration", s.run.duration_s},
                                  {"production_start", s.run.production_start_s}});
  root.insert("output", toml::table{{"snapshot_interval", s.run.snapshot_interval_s},
                                    {"series_interval", s.run.series_interval_s},
                                    {"checkpoint_interval", s.run.checkpoint_interval_s},
                                    {"progress_interval", s.run.progress_interval_s},
                                    {"sample_every", int64_t(s.run.sample_every)},
                                    {"blocks", int64_t(s.run.blocks)}});
  root.insert("numerics",
              toml::table{{"precision",
                           s.setup.precision == Precision::single_precision ? "single" : "double"},
                          {"skin", s.setup.skin_m},
                          {"mass_definition", to_string(s.mass_definition)},
                          {"bin_size", s.bin_size_m}});
  std::ostringstream os;
  os << root << "\n";
  return os.str();
}

}  // namespace granshock
