// The scene schema's sections of the domain: [domain], [inflow] and [obstacle], with every
// shape's size keys (io/scene_schema_parts.hpp).
#include <fmt/format.h>

#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "io/scene_schema_parts.hpp"
#include "io/table_reader.hpp"
#include "models/obstacle_shapes.hpp"

namespace granshock::scene_toml::schema_detail {

namespace {

// ---- [domain] ----------------------------------------------------------------------------

const Key kDomainKeys[] = {
    {"width",
     "length",
     {"m, `\"N d\"`", "`> 0`, at least 3 (d_max + `numerics.skin`), at most 1e4 m", "required",
      "crosswise x, periodic"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.box.hi[0] = r.positive_length(k);
       if (st.s.setup.box.hi[0] > kMaxDomainLength)
         fail(r.key(k), fmt::format("{} m", st.s.setup.box.hi[0]),
              fmt::format("must be at most {:g} m", kMaxDomainLength));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.box.hi[0]);
     }},
    {"length",
     "length",
     {"m, `\"N d\"`", "`> 0`, longer than `inflow.strip`, at most 1e4 m", "required",
      "streamwise y: inflow at 0, outflow at length"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.setup.box.hi[1] = r.positive_length(k);
       if (st.s.setup.box.hi[1] > kMaxDomainLength)
         fail(r.key(k), fmt::format("{} m", st.s.setup.box.hi[1]),
              fmt::format("must be at most {:g} m", kMaxDomainLength));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.setup.box.hi[1]);
     }},
    {"thickness",
     "length",
     {"m, `\"N d\"`",
      "at least d_max between walls, at least 3 interaction ranges when periodic; at most 1e4 m",
      "required when `scene.dim = 3`, refused otherwise",
      "across the layer (z), from 0 to thickness"},
     [](TableReader& r, Reading& st, const std::string& k) {
       if (st.s.setup.dim != 3) {
         if (r.has(k))
           fail(r.key(k), "(given)",
                "belongs to a 3-D scene (scene.dim = 3): a quasi-2-D "
                "scene is one diameter thick");
         return;
       }
       if (!r.has(k)) fail(r.key(k), "(missing)", "a 3-D scene (scene.dim = 3) needs it");
       st.s.setup.box.hi[2] = r.positive_length(k);
       if (st.s.setup.box.hi[2] > kMaxDomainLength)
         fail(r.key(k), fmt::format("{} m", st.s.setup.box.hi[2]),
              fmt::format("must be at most {:g} m", kMaxDomainLength));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       if (w.s.setup.dim == 3) t.insert(k, w.s.setup.box.hi[2]);
     }},
    {"z_boundary",
     "string",
     {"", "walls, periodic", "`\"walls\"`",
      "3-D only: flat frictionless walls at z = 0 and z = thickness, of the obstacle's material "
      "and restitution (a slab), or a periodic z axis"},
     [](TableReader& r, Reading& st, const std::string& k) {
       if (st.s.setup.dim != 3) {
         if (r.has(k)) fail(r.key(k), "(given)", "belongs to a 3-D scene (scene.dim = 3)");
         return;
       }
       st.s.setup.z_walls = read_choice(r, k, ZBoundary::walls) == ZBoundary::walls;
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       if (w.s.setup.dim == 3)
         t.insert(k, choice_name(w.s.setup.z_walls ? ZBoundary::walls : ZBoundary::periodic));
     }},
};
// Periodic across (x), open along the flow (y); one diameter thick (z) in 2-D, in 3-D
// `thickness` between walls or periodic.
void after_domain(Reading& st) {
  SolverSetup& setup = st.s.setup;
  const double width = setup.box.hi[0], range = setup.max_diameter() + setup.skin_m;
  if (width < 3 * range)
    fail("domain.width", fmt::format("{} m", width),
         fmt::format("must be at least 3 interaction ranges, each the largest diameter plus "
                     "numerics.skin ({} m)",
                     3 * range));
  setup.box.lo = {0, 0, 0};
  if (setup.dim == 2) setup.box.hi[2] = setup.max_diameter();
  setup.box.periodic = {true, false, setup.dim == 3 && !setup.z_walls};
  const double thickness = setup.box.hi[2];
  if (setup.dim == 3 && setup.z_walls && thickness < setup.max_diameter())
    fail("domain.thickness", fmt::format("{} m", thickness),
         fmt::format("must be at least the largest diameter ({} m) between walls",
                     setup.max_diameter()));
  if (setup.dim == 3 && !setup.z_walls && thickness < 3 * range)
    fail("domain.thickness", fmt::format("{} m", thickness),
         fmt::format("must be at least 3 interaction ranges ({} m) when z is periodic", 3 * range));
  setup.delete_outside = true;
}

// ---- [inflow] ----------------------------------------------------------------------------

const Key kInflowKeys[] = {
    {"area_fraction",
     "number",
     {"", "`[1e-6, 0.4]`", "required",
      "phi_inf; the limit is what the inflow can insert (scene_format.md, \"The inflow\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double phi = st.s.inflow.area_fraction = r.positive(k);
       if (phi < kMinAreaFraction)
         fail(r.key(k), fmt::format("{}", phi),
              fmt::format("must be at least {}: a gas that dilute leaves the field bins empty",
                          kMinAreaFraction));
       if (phi > kMaxInflowAreaFraction)
         fail(r.key(k), fmt::format("{}", phi),
              fmt::format("must be in (0, {}]: random insertion in the strip reaches about 0.42 "
                          "(measured; random sequential adsorption of discs jams at 0.547, "
                          "Hinrichsen, Feder & Jossang 1986), so more cannot be met "
                          "(docs/scene_format.md)",
                          kMaxInflowAreaFraction));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.inflow.area_fraction);
     }},
    {"velocity",
     "number (m/s)",
     {"m/s", "`[1e-6, 1e4]`", "required", "U along +y"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.inflow.speed_m_per_s = r.number_within(k, kSpeed.lo, kSpeed.hi, {}, kSpeed.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.inflow.speed_m_per_s);
     }},
    // Written back as the sigma used, also when the scene gave a Mach number.
    {"sigma",
     "number (m/s)",
     {"m/s", "`[0, 1e4]`", "one of `inflow.sigma`, `inflow.mach`",
      "Gaussian fluctuation per component"},
     [](TableReader& r, Reading& st, const std::string& k) {
       if (r.has(k) == r.has("mach"))
         fail("inflow.sigma / inflow.mach", "(both or neither)",
              "give exactly one: sigma (m/s) or mach");
       if (r.has(k))
         st.s.inflow.sigma_m_per_s = r.number_within(k, kSigma.lo, kSigma.hi, {}, kSigma.why);
     },
     [](const Writing& w, toml::table& t, const std::string& k) { t.insert(k, w.s.inflow.sigma); }},
    // Resolved into inflow.sigma (resolve_inflow), which carries it into the resolved scene.
    {"mach",
     "number",
     {"", "`[0.1, 1e4]`", "one of `inflow.sigma`, `inflow.mach`",
      "target Ma_inf; sigma follows from it (scene_format.md, \"The inflow\"); the resolved scene "
      "holds the sigma"},
     [](TableReader& r, Reading& st, const std::string& k) {
       if (r.has(k))
         st.s.inflow.target_mach = r.number_within(k, kMach.lo, kMach.hi, {}, kMach.why);
     },
     [](const Writing&, toml::table&, const std::string&) {}},
    // Where the Mach number is meant (docs/fields.md, "Three upstream Mach numbers"). Like
    // mach, it says how sigma is found; the resolved scene carries the sigma found.
    {"mach_at",
     "string",
     {"", "inserted, inlet_bins", "`\"inserted\"`",
      "where mach is meant (`inlet_bins` needs `inflow.mach`): the inserted state, or measured "
      "over the two inlet bin rows as the paper does, sigma calibrated before the run (fields.md, "
      "\"Three upstream Mach numbers\")"},
     [](TableReader& r, Reading& st, const std::string& k) {
       st.s.inflow.mach_at = read_choice(r, k, MachReference::inserted);
       if (st.s.inflow.mach_at == MachReference::inlet_bins && !st.s.inflow.target_mach)
         fail(r.key(k), fmt::format("\"{}\"", choice_name(MachReference::inlet_bins)),
              "needs inflow.mach, the Mach number to calibrate sigma for");
     },
     [](const Writing&, toml::table&, const std::string&) {}},
    {"strip",
     "length",
     {"m, `\"N d\"`", "at least d_max, shorter than `domain.length`", "`\"2 d\"`",
      "insertion strip y in [0, strip]"},
     [](TableReader& r, Reading& st, const std::string& k) {
       const double strip = st.s.inflow.strip_m = r.length(k, 2 * st.s.d_m);
       if (strip < st.s.setup.max_diameter() || strip >= st.s.setup.box.hi[1])
         fail(r.key(k), fmt::format("{} m", strip),
              fmt::format("must be at least one diameter and shorter than domain.length ({} m)",
                          st.s.setup.box.hi[1]));
     },
     [](const Writing& w, toml::table& t, const std::string& k) {
       t.insert(k, w.s.inflow.strip_m);
     }},
};

// ---- [obstacle] --------------------------------------------------------------------------

// The size keys of the shapes (docs/scene_format.md, [obstacle]), each declared once in its
// shape's header (`keys`, models/shape_key.hpp) and found here by name: a key is
// read into Obstacle::size when the obstacle has a shape that owns it, refused when it is
// given for another shape, and written back for its own shape only.
void read_shape_key(TableReader& r, Reading& st, const std::string& k) {
  const ObstacleShape shape = st.obstacle.shape;
  const std::optional<std::size_t> own = shape_key_index(shape, k);
  if (!own) {
    if (const toml::node* n = r.node(k))
      fail(r.key(k), show(*n),
           fmt::format("is a key of obstacle.shape = {}, and the shape is \"{}\"",
                       quoted_names(shapes_with_key(k)), choice_name(shape)));
    return;
  }
  const ShapeKey key = with_obstacle_shape(shape, [&](auto s) { return s.keys[*own]; });
  const std::optional<double> fallback =
      key.required() ? std::nullopt : std::optional<double>(key.fallback);
  double value = 0;
  if (key.kind == ShapeKey::Kind::angle) {
    value = r.number_in(k, key.lo, key.hi, !key.lo_closed, true, fallback);
  } else {
    value = r.positive_length(k, fallback);
    if (value < st.s.setup.max_diameter())
      fail(r.key(k), fmt::format("{} m", value),
           fmt::format("must be at least the largest particle diameter ({} m): the contact "
                       "law treats the {} as a wall",
                       st.s.setup.max_diameter(), choice_name(shape)));
  }
  st.obstacle.size[*own] = value;
}

void write_shape_key(const Writing& w, toml::table& t, const std::string& k) {
  const Obstacle& o = *w.s.setup.obstacle;
  if (const std::optional<std::size_t> own = shape_key_index(o.shape, k)) t.insert(k, o.size[*own]);
}

// A shape key's row of docs/scene_keys.md, from its shape's declaration (every shape that
// declares the name owns it; the range, default and meaning are the first's).
KeyDoc shape_key_doc(const ShapeKey& key) {
  std::vector<std::string> owners;
  for (ObstacleShape shape : shapes_with_key(key.name))
    owners.push_back(fmt::format("a {}", choice_name(shape)));
  const std::string shapes = fmt::format("{}", fmt::join(owners, " or "));
  const bool length = key.kind == ShapeKey::Kind::length;
  return {
      length ? "m, `\"N d\"`" : "degrees",
      length ? std::string("at least d_max (the contact law treats the obstacle as a wall)")
             : fmt::format("`{}{}, {})`", key.lo_closed ? "[" : "(", short_number(key.lo),
                           short_number(key.hi)),
      key.required() ? "required for " + shapes : fmt::format("`{}`", short_number(key.fallback)),
      key.required() ? key.meaning : fmt::format("{} only: {}", shapes, key.meaning)};
}

// [obstacle]'s keys: the shape, every shape's size keys (each name once, in the order of
// ObstacleShapes), the material and the centre.
std::vector<Key> obstacle_keys() {
  std::vector<Key> keys = {
      {"shape",
       "string",
       {"", "cylinder, wedge, plate, square, sphere", "`\"cylinder\"`",
        "a fixed prism along z: its cross-section, or a sphere (scene_format.md, \"Obstacle "
        "shapes\"); a "
        "`[obstacle]` table makes the obstacle (no table: no obstacle), and each shape takes only "
        "its own size keys"},
       [](TableReader& r, Reading& st, const std::string& k) {
         st.obstacle.shape = read_choice(r, k, ObstacleShape::cylinder);
       },
       [](const Writing& w, toml::table& t, const std::string& k) {
         t.insert(k, choice_name(w.s.setup.obstacle->shape));
       }},
  };
  for_each_obstacle_shape([&](auto s) {
    for (const ShapeKey& key : s.keys)
      add_owned_key(keys, key.name, key.type(), shape_key_doc(key), read_shape_key,
                    write_shape_key);
  });
  keys.push_back({"material",
                  "string",
                  {"", "a material", "`\"aluminium\"`",
                   "the obstacle's modulus and Poisson ratio in its contacts (it does not move)"},
                  [](TableReader& r, Reading& st, const std::string& k) {
                    st.obstacle.material = material_named(st, r.key(k), r.string(k, "aluminium"));
                  },
                  [](const Writing& w, toml::table& t, const std::string& k) {
                    t.insert(k, w.s.setup.obstacle->material.name);
                  }});
  keys.push_back({"centre",
                  "[length, length]",
                  {"m, `\"N d\"`",
                   "the shape inside the domain, its upstream end at least d_max past "
                   "`inflow.strip`, and a gap of at least 3 d_max beside it across the channel",
                   "`[domain.width / 2, domain.length / 2]`",
                   "the middle of the shape's extent along x and y (a cylinder's axis; half-way "
                   "from a wedge's tip to its base)"},
                  [](TableReader& r, Reading& st, const std::string& k) {
                    const Box& box = st.s.setup.box;
                    // In 3-D the middle of the layer (a sphere's centre).
                    st.obstacle.centre = {0.5 * box.hi[0], 0.5 * box.hi[1],
                                          st.s.setup.dim == 3 ? 0.5 * box.hi[2] : 0};
                    if (const toml::node* n = r.node(k)) {
                      const toml::array* a = n->as_array();
                      if (!a || a->size() != 2)
                        fail(r.key(k), show(*n), "must be [x, y] (two lengths)");
                      st.obstacle.centre[0] = r.length_of(*a->get(0), r.key(k) + "[0]");
                      st.obstacle.centre[1] = r.length_of(*a->get(1), r.key(k) + "[1]");
                    }
                  },
                  [](const Writing& w, toml::table& t, const std::string& k) {
                    const auto& c = w.s.setup.obstacle->centre;
                    t.insert(k, toml::array{c[0], c[1]});
                  }});
  return keys;
}
const std::vector<Key> kObstacleKeys = obstacle_keys();

// The least gap an obstacle leaves across the periodic channel, in particle diameters.
constexpr double kMinObstacleGapDiameters = 3;

// The keys that set the shape's width across the flow (the D of delta/D): those of its
// size keys whose change moves the width (a plate's width, not its thickness).
std::string frontal_width_keys(const Obstacle& c) {
  return with_obstacle_shape(c, [&](auto s) {
    std::vector<std::string> keys;
    for (std::size_t k = 0; k < std::size(s.keys); ++k) {
      Obstacle changed = c;
      changed.size[k] = c.size[k] == 0 ? 1.0 : 1.01 * c.size[k];
      if (obstacle_frontal_width(changed) != obstacle_frontal_width(c))
        keys.push_back(std::string("obstacle.") + s.keys[k].name);
    }
    return fmt::format("{}", fmt::join(keys, "' and '"));
  });
}

void after_obstacle(Reading& st) {
  const Obstacle& c = st.obstacle;
  const double across = 0.5 * obstacle_frontal_width(c), width = st.s.setup.box.hi[0];
  const double along = 0.5 * obstacle_streamwise_length(c), length = st.s.setup.box.hi[1];
  if (c.centre[0] - across < 0 || c.centre[0] + across > width ||
      c.centre[1] - along < st.s.inflow.strip_m + st.s.setup.max_diameter() ||
      c.centre[1] + along > length)
    fail("obstacle",
         fmt::format("centre ({}, {}) m, {} ({} m across and {} m along the flow)", c.centre[0],
                     c.centre[1], obstacle_size_text(c), 2 * across, 2 * along),
         fmt::format("the {} must lie inside the domain, downstream of the insertion strip",
                     choice_name(c.shape)));
  // The periodic channel beside it: an obstacle as wide as the domain closes it, and the
  // flow it is there to divert piles up in front of it instead.
  const double gap = width - 2 * across, d = st.s.setup.max_diameter();
  if (gap < kMinObstacleGapDiameters * d)
    fail(
        frontal_width_keys(c),
        fmt::format("{} m across the flow, in a channel of domain.width = {} m", 2 * across, width),
        fmt::format("the {} leaves a gap of {:.3g} particle diameters beside it; it must leave "
                    "at least {:g} for the flow to pass: make it narrower or the domain wider",
                    choice_name(c.shape), gap / d, kMinObstacleGapDiameters));
  st.s.setup.obstacle = c;
  st.s.setup.wall_material = c.material;  // a slab's walls
}

}  // namespace

const Table kDomain = table("domain", kDomainKeys, after_domain);
const Table kInflow = table("inflow", kInflowKeys);
const Table kObstacle = {"obstacle", kObstacleKeys.data(), kObstacleKeys.size(), after_obstacle};

}  // namespace granshock::scene_toml::schema_detail
