// SPDX-License-Identifier: MIT
#include "xfem/system/problem.h"

#include <cmath>
#include <fstream>
#include <initializer_list>

#include <algorithm>
#include <array>
#include <map>

#include "xfem/core/boundary_groups.h"
#include "xfem/core/regions.h"
#include "xfem/core/error.h"

namespace xfem {
namespace {

// A cursor into the JSON document that knows its path ("dirichlet[1].selector") for messages.
struct Node {
  const Json& j;
  std::string file, path;

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(file + ": " + (path.empty() ? "" : path + " ") + what);
  }
  std::string child_path(const std::string& key) const { return path.empty() ? key : path + "." + key; }

  void require_object(std::initializer_list<const char*> allowed) const {
    if (!j.is_object()) fail("must be an object");
    for (const auto& item : j.items()) {
      bool known = false;
      for (const char* a : allowed) known = known || item.key() == a;
      if (!known) {
        std::string list;
        for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
        throw Error(file + ": unknown key '" + child_path(item.key()) + "' (allowed here: " + list + ")");
      }
    }
  }
  bool has(const char* key) const { return j.contains(key); }
  Node at(const char* key) const {
    if (!j.contains(key)) throw Error(file + ": missing field '" + child_path(key) + "'");
    return {j.at(key), file, child_path(key)};
  }
  Node at(std::size_t i) const { return {j.at(i), file, path + "[" + std::to_string(i) + "]"}; }

  double number() const {
    if (!j.is_number()) fail("must be a number");
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail("must be finite");
    return v;
  }
  std::string string() const {
    if (!j.is_string()) fail("must be a string");
    return j.get<std::string>();
  }
  std::size_t array_size() const {
    if (!j.is_array()) fail("must be a list");
    return j.size();
  }
  Eigen::Vector3d vector3() const {
    if (!j.is_array() || j.size() != 3) fail("must be a list of 3 numbers");
    return Eigen::Vector3d(at(std::size_t{0}).number(), at(1).number(), at(2).number());
  }
};

Selector parse_selector(const Node& n) {
  n.require_object({"half_spaces", "box", "point_array", "group", "boundary"});
  if (n.j.size() != 1) n.fail("must have exactly one of half_spaces, box, point_array, group, boundary");
  Selector s;
  if (n.has("boundary")) {
    // Only true: "boundary": false would select nothing, or everything else, and says neither.
    const Node b = n.at("boundary");
    if (!b.j.is_boolean() || !b.j.get<bool>())
      b.fail("must be true (the nodes of the mesh's boundary faces), got " + b.j.dump());
    s.kind = Selector::Kind::Boundary;
  } else if (n.has("half_spaces")) {
    s.kind = Selector::Kind::HalfSpaces;
    const Node list = n.at("half_spaces");
    if (list.array_size() == 0) list.fail("must list at least one plane");
    for (std::size_t i = 0; i < list.j.size(); ++i) {
      const Node plane = list.at(i);
      plane.require_object({"point", "normal"});
      const Eigen::Vector3d p = plane.at("point").vector3(), normal = plane.at("normal").vector3();
      if (normal.norm() == 0.0) plane.at("normal").fail("must not be zero");
      s.planes.emplace_back(p, normal);
    }
  } else if (n.has("box")) {
    s.kind = Selector::Kind::Box;
    const Node box = n.at("box");
    box.require_object({"lo", "hi"});
    s.lo = box.at("lo").vector3();
    s.hi = box.at("hi").vector3();
    if ((s.hi.array() < s.lo.array()).any()) box.fail("is empty (hi must be >= lo in x, y and z)");
  } else if (n.has("group")) {
    s.kind = Selector::Kind::Group;
    s.array = n.at("group").string();
    if (s.array.empty()) n.at("group").fail("must name a group");
  } else {
    s.kind = Selector::Kind::PointArray;
    s.array = n.at("point_array").string();
  }
  return s;
}

Eigen::Vector3d unit(const Node& n) {
  const Eigen::Vector3d v = n.vector3();
  if (v.norm() == 0.0) n.fail("must not be zero");
  return v.normalized();
}

double optional_number(const Node& n, const char* key, double fallback) {
  return n.has(key) ? n.at(key).number() : fallback;
}

void check_material(const Node& n, double E, double nu) {
  if (!(E > 0)) n.fail("E must be positive, got " + short_number(E));
  if (!(nu > -1.0 && nu < 0.5)) n.fail("nu must lie in (-1, 0.5), got " + short_number(nu));
}

// E, nu and the optional model of a material object (`material` or an entry of `materials`).
void parse_material(const Node& material, double& E, double& nu, MaterialModel& model) {
  E = material.at("E").number();
  if (!(E > 0)) material.at("E").fail("must be positive, got " + material.at("E").j.dump());
  nu = material.at("nu").number();
  if (!(nu > -1.0 && nu < 0.5)) material.at("nu").fail("must lie in (-1, 0.5), got " + material.at("nu").j.dump());
  if (material.has("model")) {
    const Node m = material.at("model");
    const std::string name = m.string();
    try {
      model = material_model_named(name);
    } catch (const Error&) {
      m.fail("must be \"linear\", \"corotational\" or \"neo-hookean\", got \"" + name + "\"");
    }
  }
}

RigidMotion parse_rigid_motion(const Node& n) {
  n.require_object({"translation", "rotation", "centre"});
  RigidMotion m;
  if (n.has("translation")) m.translation = n.at("translation").vector3();
  if (n.has("rotation")) m.rotation = n.at("rotation").vector3();
  if (n.has("centre")) m.centre = n.at("centre").vector3();
  return m;
}

ExactField parse_exact(const Node& n, const std::optional<std::pair<double, double>>& material) {
  n.require_object({"williams", "rigid", "linear", "penny"});
  if (n.j.size() != 1) n.fail("must have exactly one of williams, rigid, linear, penny");
  ExactField f;
  if (n.has("williams")) {
    const Node w = n.at("williams");
    w.require_object({"origin", "ahead", "normal", "K1", "K2", "K3", "E", "nu"});
    f.kind = ExactField::Kind::Williams;
    WilliamsField& W = f.williams;
    W.origin = w.at("origin").vector3();
    W.a = unit(w.at("ahead"));
    W.b = unit(w.at("normal"));
    if (std::abs(W.a.dot(W.b)) > 1e-9) w.fail("ahead and normal must be perpendicular");
    W.K1 = optional_number(w, "K1", 0.0);
    W.K2 = optional_number(w, "K2", 0.0);
    W.K3 = optional_number(w, "K3", 0.0);
    if (!material && !(w.has("E") && w.has("nu"))) w.fail("needs E and nu (the material of the field)");
    W.E = w.has("E") ? w.at("E").number() : material->first;
    W.nu = w.has("nu") ? w.at("nu").number() : material->second;
    check_material(w, W.E, W.nu);
  } else if (n.has("penny")) {
    const Node w = n.at("penny");
    w.require_object({"centre", "normal", "radius", "sigma", "shear", "E", "nu", "loading", "friction"});
    f.kind = ExactField::Kind::Penny;
    PennyField& P = f.penny;
    if (w.has("centre")) P.centre = w.at("centre").vector3();
    P.normal = unit(w.at("normal"));
    P.radius = w.at("radius").number();
    if (!(P.radius > 0)) w.at("radius").fail("must be positive, got " + short_number(P.radius));
    P.sigma = w.at("sigma").number();
    if (w.has("shear")) {
      P.shear = w.at("shear").vector3();
      if (std::abs(P.shear.dot(P.normal)) > 1e-9 * P.shear.norm())
        w.at("shear").fail("must lie in the disc's plane (perpendicular to normal)");
    }
    if (w.has("loading")) {  // "remote" tension (the default) or "faces": the same load on the disc's faces
      const std::string loading = w.at("loading").string();
      if (loading != "remote" && loading != "faces" && loading != "closed")
        w.at("loading").fail("must be \"remote\", \"faces\" or \"closed\", got \"" + loading + "\"");
      P.remote = loading != "faces";
      P.closed = loading == "closed";  // faces pressed shut by a remote compression (contact)
      if (P.closed && !(P.sigma <= 0))
        w.at("sigma").fail("must be <= 0 with \"loading\": \"closed\" (faces pressed shut), got " + short_number(P.sigma));
    }
    if (w.has("friction")) {  // Coulomb friction between the shut faces (issue 33)
      P.friction = w.at("friction").number();
      if (!P.closed) w.at("friction").fail("needs \"loading\": \"closed\" (friction acts between shut faces)");
      if (!(P.friction >= 0)) w.at("friction").fail("must be >= 0, got " + short_number(P.friction));
    }
    if (!material && !(w.has("E") && w.has("nu"))) w.fail("needs E and nu (the material of the field)");
    P.E = w.has("E") ? w.at("E").number() : material->first;
    P.nu = w.has("nu") ? w.at("nu").number() : material->second;
    check_material(w, P.E, P.nu);
  } else if (n.has("linear")) {
    const Node l = n.at("linear");
    l.require_object({"gradient", "translation"});
    f.kind = ExactField::Kind::Linear;
    const Node g = l.at("gradient");
    if (g.array_size() != 3) g.fail("must be a list of 3 rows of 3 numbers");
    for (std::size_t i = 0; i < 3; ++i) f.linear_gradient.row(static_cast<Eigen::Index>(i)) = g.at(i).vector3().transpose();
    if (l.has("translation")) f.linear_translation = l.at("translation").vector3();
  } else {
    const Node r = n.at("rigid");
    r.require_object({"above", "below"});
    f.kind = ExactField::Kind::Rigid;
    if (r.has("above")) f.above = parse_rigid_motion(r.at("above"));
    if (r.has("below")) f.below = parse_rigid_motion(r.at("below"));
  }
  return f;
}

// A finite rigid motion (DirichletCondition::rotation): the axis need not be a unit vector.
PrescribedRotation parse_rotation(const Node& n) {
  n.require_object({"axis", "angle_deg", "center", "translation"});
  PrescribedRotation r;
  r.axis = unit(n.at("axis"));
  r.angle = n.at("angle_deg").number() * (M_PI / 180.0);
  if (n.has("center")) r.centre = n.at("center").vector3();
  if (n.has("translation")) r.translation = n.at("translation").vector3();
  return r;
}

std::string optional_name(const Node& n) { return n.has("name") ? n.at("name").string() : std::string(); }

// A cut index: a non-negative integer (below kMaxCuts; the mesh's own count is checked later).
int cut_index(const Node& n) {
  if (!n.j.is_number_integer() || n.j.get<long>() < 0 || n.j.get<long>() > 15)
    n.fail("must be a cut index, an integer in 0..15, got " + n.j.dump());
  return n.j.get<int>();
}

// "cut_loads": [{"cut": 0, "pressure": p, "traction": [tx, ty, tz]}, ...] (CutLoad).
void parse_cut_loads(const Node& root, Problem& p) {
  if (!root.has("cut_loads")) return;
  const Node list = root.at("cut_loads");
  for (std::size_t i = 0; i < list.array_size(); ++i) {
    const Node c = list.at(i);
    c.require_object({"cut", "pressure", "traction"});
    if (!c.has("pressure") && !c.has("traction")) c.fail("needs a pressure or a traction (or both)");
    CutLoad load;
    load.cut = c.has("cut") ? cut_index(c.at("cut")) : 0;
    if (c.has("pressure")) load.pressure = c.at("pressure").number();
    if (c.has("traction")) load.traction = c.at("traction").vector3();
    p.cut_loads.push_back(load);
  }
}

// "friction": mu | [mu per entry of "cuts"] inside "contact" (ContactSettings::friction): mu >= 0.
void parse_friction(const Node& c, Problem& p) {
  if (!c.has("friction")) return;
  const Node f = c.at("friction");
  const auto coefficient = [](const Node& n) {
    const double mu = n.number();
    if (!(mu >= 0.0 && mu <= 1e3)) n.fail("must lie in 0..1e3 (a friction coefficient), got " + n.j.dump());
    return mu;
  };
  p.contact.friction_on = true;
  if (!f.j.is_array()) {
    p.contact.friction.push_back(coefficient(f));
    return;
  }
  if (!c.has("cuts") || f.j.size() != p.contact.cuts.size())
    f.fail("a list needs one coefficient per entry of \"cuts\" (" + std::to_string(p.contact.cuts.size()) +
           "), got " + std::to_string(f.j.size()) + " (or give one number for every cut)");
  for (std::size_t i = 0; i < f.j.size(); ++i) p.contact.friction.push_back(coefficient(f.at(i)));
}

// "contact": true | false | {"cuts": [0, 2], "penalty": 1e3, "friction": 0.3} (ContactSettings).
void parse_contact(const Node& root, Problem& p) {
  if (!root.has("contact")) return;
  const Node c = root.at("contact");
  if (c.j.is_boolean()) {
    p.contact.on = c.j.get<bool>();  // every cut
    return;
  }
  if (!c.j.is_object()) c.fail("must be true, false or an object {\"cuts\": [...], \"penalty\": ...}");
  c.require_object({"cuts", "penalty", "friction"});
  if (c.has("penalty")) {
    p.contact.penalty = c.at("penalty").number();
    if (!(p.contact.penalty >= 1.0 && p.contact.penalty <= 1e8))
      c.at("penalty").fail("must lie in 1..1e8 (kappa = penalty E / h), got " + c.at("penalty").j.dump());
  }
  p.contact.on = true;
  if (!c.has("cuts")) return parse_friction(c, p);
  const Node cuts = c.at("cuts");
  if (cuts.array_size() == 0) cuts.fail("must list at least one cut index (or give \"contact\": false)");
  for (std::size_t i = 0; i < cuts.j.size(); ++i) {
    const int k = cut_index(cuts.at(i));
    for (int other : p.contact.cuts)
      if (other == k) cuts.at(i).fail("names cut " + std::to_string(k) + " twice");
    p.contact.cuts.push_back(k);
  }
  parse_friction(c, p);
}

}  // namespace

Problem parse_problem(const Json& j, const std::string& file) {
  const Node root{j, file, ""};
  // Friction acts between faces in contact: its coefficient belongs to "contact".
  if (root.has("friction"))
    root.at("friction").fail("must be given inside \"contact\" (\"contact\": {\"friction\": mu}): friction needs contact");
  root.require_object({"description", "material", "materials", "integration", "dirichlet", "neumann", "body_force",
                       "load_steps", "cut_loads", "contact"});
  Problem p;
  p.file = file;
  if (root.has("description")) root.at("description").string();
  const Node material = root.at("material");
  material.require_object({"E", "nu", "model"});
  parse_material(material, p.E, p.nu, p.model);
  if (root.has("materials")) {
    const Node list = root.at("materials");
    for (std::size_t i = 0; i < list.array_size(); ++i) {
      const Node m = list.at(i);
      m.require_object({"region", "E", "nu", "model"});
      RegionMaterial r;
      r.model = p.model;  // a region without "model" has the default's
      const Node region = m.at("region");
      if (region.j.is_string()) {
        r.name = region.string();
        if (r.name.empty()) region.fail("must name a region (a non-empty string) or be its id");
      } else if (region.j.is_number_integer() && region.j.get<long long>() >= 0 &&
                 region.j.get<long long>() <= max_region_id) {
        r.id = region.j.get<int>();
      } else {
        region.fail("must be a region id (an integer in 0.." + std::to_string(max_region_id) + ") or a name, got " +
                    region.j.dump());
      }
      parse_material(m, r.E, r.nu, r.model);
      for (std::size_t k = 0; k < p.materials.size(); ++k)
        if ((r.id >= 0 && p.materials[k].id == r.id) || (!r.name.empty() && p.materials[k].name == r.name))
          region.fail("lists region " + region.j.dump() + " again (materials[" + std::to_string(k) +
                      "] gives its material)");
      p.materials.push_back(r);
    }
  }
  if (root.has("load_steps")) {
    const Node steps = root.at("load_steps");
    if (!steps.j.is_number_integer() || steps.j.get<long>() < 1 || steps.j.get<long>() > 1000000)
      steps.fail("must be an integer in 1..1000000, got " + steps.j.dump());
    p.load_steps = steps.j.get<int>();
  }
  if (root.has("integration")) {
    const Node integration = root.at("integration");
    integration.require_object({"points", "refine", "rule", "order"});
    if (integration.has("rule")) {
      const Node rule = integration.at("rule");
      const std::string name = rule.string();
      if (name != "oversampling" && name != "conforming" && name != "graded" && name != "pieces")
        rule.fail("must be \"oversampling\", \"conforming\", \"graded\" or \"pieces\", got \"" + name + "\"");
      p.rule = name == "oversampling" ? Problem::Rule::Oversampling : Problem::Rule::Conforming;
      p.closed_form = name != "pieces";
      p.graded = name == "graded";
    } else if (integration.has("points") || integration.has("refine")) {
      p.rule = Problem::Rule::Oversampling;  // files written before the conforming default keep their meaning
    }
    if (integration.has("order")) {
      const Node order = integration.at("order");
      if (!order.j.is_number_integer() || order.j.get<long>() < 1 || order.j.get<long>() > 20)
        order.fail("must be an integer in 1..20, got " + order.j.dump());
      p.order = order.j.get<int>();
    }
    if (integration.has("points")) {
      const Node points = integration.at("points");
      if (!points.j.is_number_integer() || points.j.get<long>() < 1 || points.j.get<long>() > 100000)
        points.fail("must be an integer in 1..100000, got " + points.j.dump());
      p.points = points.j.get<int>();
    }
    if (integration.has("refine")) {
      const Node refine = integration.at("refine");
      if (!refine.j.is_number_integer() || refine.j.get<long>() < 0 || refine.j.get<long>() > 8)
        refine.fail("must be an integer in 0..8, got " + refine.j.dump());
      p.refine = refine.j.get<int>();
    }
  }
  if (root.has("dirichlet")) {
    const Node list = root.at("dirichlet");
    for (std::size_t i = 0; i < list.array_size(); ++i) {
      const Node c = list.at(i);
      c.require_object({"name", "selector", "value", "exact", "enriched_dofs", "rotation", "value_array"});
      DirichletCondition d;
      d.name = optional_name(c);
      d.selector = parse_selector(c.at("selector"));
      if (c.has("value") + c.has("exact") + c.has("rotation") + c.has("value_array") != 1)
        c.fail("must have exactly one of value, exact, rotation, value_array");
      if (c.has("enriched_dofs") && !c.has("exact")) c.at("enriched_dofs").fail("applies to an exact condition only");
      if (c.has("rotation")) {
        d.rotation = parse_rotation(c.at("rotation"));
        p.dirichlet.push_back(d);
        continue;
      }
      if (c.has("value_array")) {
        d.value_array = c.at("value_array").string();
        if (d.value_array.empty()) c.at("value_array").fail("must name a point array of the mesh");
        p.dirichlet.push_back(d);
        continue;
      }
      if (c.has("exact")) {
        d.exact = parse_exact(c.at("exact"), std::make_pair(p.E, p.nu));
        if (c.has("enriched_dofs")) {
          const Node e = c.at("enriched_dofs");
          const std::string mode = e.string();
          if (mode != "free" && mode != "exact") e.fail("must be \"free\" or \"exact\", got \"" + mode + "\"");
          d.exact_enriched = mode == "exact";
          if (d.exact_enriched && d.exact->kind != ExactField::Kind::Williams)
            e.fail("\"exact\" needs a williams field (a rigid motion has no crack-tip coefficients)");
        }
        p.dirichlet.push_back(d);
        continue;
      }
      const Node value = c.at("value");
      if (!value.j.is_array() || value.j.size() != 3) value.fail("must be a list of 3 numbers or nulls");
      bool any = false;
      for (std::size_t k = 0; k < 3; ++k)
        if (!value.j[k].is_null()) {
          d.value[k] = value.at(k).number();
          any = true;
        }
      if (!any) value.fail("leaves every component free (null): the condition does nothing");
      p.dirichlet.push_back(d);
    }
  }
  if (root.has("neumann")) {
    const Node list = root.at("neumann");
    for (std::size_t i = 0; i < list.array_size(); ++i) {
      const Node c = list.at(i);
      c.require_object({"name", "selector", "traction"});
      NeumannCondition nc;
      nc.name = optional_name(c);
      nc.selector = parse_selector(c.at("selector"));
      nc.traction = c.at("traction").vector3();
      p.neumann.push_back(nc);
    }
  }
  if (root.has("body_force")) p.body_force = root.at("body_force").vector3();
  parse_cut_loads(root, p);
  parse_contact(root, p);
  return p;
}

Problem read_problem(const std::string& path) {
  if (!std::ifstream(path)) throw Error(path + ": cannot open the problem file (does it exist?)");
  return parse_problem(read_json(path), path);
}

ExactField parse_exact_field(const Json& j, const std::string& file, const std::string& path,
                             const std::optional<std::pair<double, double>>& material) {
  return parse_exact(Node{j, file, path}, material);
}

ExactField read_exact_field(const std::string& path) {
  if (!std::ifstream(path)) throw Error(path + ": cannot open the exact-field file (does it exist?)");
  return parse_exact_field(read_json(path), path, "");
}

std::string describe(const Problem& p, const char* list, std::size_t i) {
  const std::string& name = std::string(list) == "dirichlet" ? p.dirichlet.at(i).name : p.neumann.at(i).name;
  return p.file + ": " + list + "[" + std::to_string(i) + "]" + (name.empty() ? "" : " ('" + name + "')");
}

std::vector<int> select_nodes(const Selector& s, const TetMesh& mesh, const std::string& what) {
  const Eigen::Index np = mesh.points.rows();
  const DataArray* array = nullptr;
  if (s.kind == Selector::Kind::PointArray) {
    const auto it = mesh.point_data.find(s.array);
    if (it == mesh.point_data.end()) throw Error(what + ": the mesh has no point array '" + s.array + "'");
    if (it->second.components != 1 || static_cast<Eigen::Index>(it->second.tuples()) != np)
      throw Error(what + ": point array '" + s.array + "' must have 1 component per point");
    array = &it->second;
  }
  if (s.kind == Selector::Kind::Group) {
    const auto it = mesh.point_data.find(group_array_name(s.array));
    if (it == mesh.point_data.end()) {
      std::string names;
      for (const std::string& g : group_names(mesh)) names += (names.empty() ? "'" : ", '") + g + "'";
      throw Error(what + ": the mesh has no group '" + s.array + "' (" +
                  (names.empty() ? std::string("it has no groups: name them as gmsh physical groups, docs/FORMATS.md")
                                 : "its groups: " + names) + ")");
    }
    if (it->second.components != 1 || static_cast<Eigen::Index>(it->second.tuples()) != np)
      throw Error(what + ": point array '" + it->first + "' must have 1 component per point");
    array = &it->second;
  }
  if (s.kind == Selector::Kind::Boundary) {
    std::vector<int> nodes = boundary_nodes(mesh);
    if (nodes.empty()) throw Error(what + " selects no node (the mesh has no tet)");
    return nodes;
  }
  std::vector<int> nodes;
  for (Eigen::Index k = 0; k < np; ++k) {
    const Eigen::Vector3d x = mesh.points.row(k).transpose();
    bool in = true;
    switch (s.kind) {
      case Selector::Kind::HalfSpaces:
        for (const auto& [point, normal] : s.planes) in = in && (x - point).dot(normal) > 0;
        break;
      case Selector::Kind::Box:
        in = (x.array() >= s.lo.array()).all() && (x.array() <= s.hi.array()).all();
        break;
      case Selector::Kind::PointArray:
      case Selector::Kind::Group:
        in = (*array)(k) != 0.0;
        break;
      case Selector::Kind::Boundary:  // returned above
        break;
    }
    if (in) nodes.push_back(static_cast<int>(k));
  }
  if (nodes.empty()) throw Error(what + " selects no node");
  return nodes;
}

std::vector<int> boundary_nodes(const TetMesh& mesh) {
  std::vector<char> on(mesh.points.rows(), 0);
  for (const auto& face : boundary_faces(mesh))
    for (int k : face) on[k] = 1;
  std::vector<int> nodes;
  for (std::size_t k = 0; k < on.size(); ++k)
    if (on[k]) nodes.push_back(static_cast<int>(k));
  return nodes;
}

void check_cut_indices(const Problem& problem, int cuts) {
  const std::string range = std::to_string(cuts) + (cuts == 1 ? " cut" : " cuts") +
                            (cuts > 0 ? " (indices 0.." + std::to_string(cuts - 1) + ")" : "");
  for (std::size_t i = 0; i < problem.cut_loads.size(); ++i)
    if (problem.cut_loads[i].cut >= cuts)
      throw Error(problem.file + ": cut_loads[" + std::to_string(i) + "].cut is " +
                  std::to_string(problem.cut_loads[i].cut) + ", but the mesh has " + range);
  for (std::size_t i = 0; i < problem.contact.cuts.size(); ++i)
    if (problem.contact.cuts[i] >= cuts)
      throw Error(problem.file + ": contact.cuts[" + std::to_string(i) + "] is " +
                  std::to_string(problem.contact.cuts[i]) + ", but the mesh has " + range);
}

void refuse_friction(const Problem& problem, const std::string& reason) {
  if (!problem.contact.friction_on) return;
  throw Error(problem.file + ": " + reason + ": contact.friction is solved by xfem-solve only");
}

void refuse_cut_loads_and_contact(const Problem& problem, const std::string& reason) {
  if (problem.cut_loads.empty() && !problem.contact.on) return;
  throw Error(problem.file + ": " + reason + ": " + (problem.cut_loads.empty() ? "contact is" : problem.contact.on ? "cut_loads and contact are" : "cut_loads are") +
              " solved by xfem-assemble and xfem-solve only");
}

void require_linear_material(const Problem& problem, const std::string& reason) {
  std::string where = "material.model";
  MaterialModel model = problem.model;
  for (std::size_t i = 0; i < problem.materials.size() && model == MaterialModel::Linear; ++i) {
    model = problem.materials[i].model;
    where = "materials[" + std::to_string(i) + "].model";
  }
  if (model == MaterialModel::Linear) return;
  const std::string name = material_model_name(model);
  throw Error(problem.file + ": " + reason + ": " + where + " \"" + name + "\" is not supported (use \"linear\"; " +
              "xfem-newton solves \"" + name + "\")");
}

TetMaterials tet_materials(const Problem& problem, const TetMesh& mesh, const std::string& mesh_file) {
  TetMaterials out(problem.model, problem.E, problem.nu);
  if (problem.materials.empty()) return out;
  const std::vector<int> region = tet_regions(mesh);
  const std::vector<int> ids = region_ids(mesh);
  std::map<int, int> law_of;  // region id -> index into out.laws (equal materials share one)
  for (std::size_t i = 0; i < problem.materials.size(); ++i) {
    const RegionMaterial& m = problem.materials[i];
    int id = m.id;
    if (!m.name.empty())
      for (const auto& [named, name] : mesh.region_names)
        if (name == m.name) id = named;
    const bool known = id >= 0 && (std::binary_search(ids.begin(), ids.end(), id) || mesh.region_names.count(id));
    if (!known)
      throw Error(problem.file + ": materials[" + std::to_string(i) + "].region " +
                  (m.name.empty() ? std::to_string(m.id) : "'" + m.name + "'") + " is not a region of " + mesh_file +
                  " (its regions: " + region_list(mesh) + ")");
    if (law_of.count(id))
      throw Error(problem.file + ": materials[" + std::to_string(i) + "].region names region " + std::to_string(id) +
                  " again (materials lists each region once)");
    law_of[id] = out.add(m.model, m.E, m.nu);
  }
  out.of_tet.resize(region.size());
  bool all_default = true;
  for (std::size_t t = 0; t < region.size(); ++t) {
    const auto it = law_of.find(region[t]);
    out.of_tet[t] = it == law_of.end() ? 0 : it->second;
    all_default = all_default && out.of_tet[t] == 0;
  }
  if (all_default) {  // one material: the single-material code path
    out.of_tet.clear();
    out.laws.resize(1);
    out.E.resize(1);
    out.nu.resize(1);
  }
  return out;
}

}  // namespace xfem
