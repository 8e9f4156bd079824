// options.cpp -- see options.h.
#include "tools/options.h"

#include "medial3/mesh/mesh_repair.h"
#include "support/progress.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace grassfire::cli {

Options::Options(std::string command, std::string summary)
    : command_(std::move(command)), summary_(std::move(summary)) {}

Options& Options::positional(const std::string& name, const std::string& help, bool required) {
  if (required && required_positionals_ < positionals_.size())
    throw std::logic_error("options: a required positional after an optional one");
  positionals_.emplace_back(name, help);
  if (required) ++required_positionals_;
  return *this;
}

Options& Options::flag(const std::string& name, const std::string& help) {
  specs_.push_back({name, "", help, false, std::nullopt});
  return *this;
}

Options& Options::option(const std::string& name, const std::string& value_name, const std::string& help,
                         std::optional<std::string> default_value) {
  specs_.push_back({name, value_name, help, true, std::move(default_value)});
  return *this;
}

Options& Options::epilog(const std::string& text) {
  epilog_ = text;
  return *this;
}

const Options::Spec* Options::find(const std::string& name) const {
  for (const Spec& s : specs_)
    if (s.name == name) return &s;
  return nullptr;
}

std::string Options::usage() const {
  std::ostringstream os;
  os << "usage: grassfire " << command_;
  for (std::size_t i = 0; i < positionals_.size(); ++i)
    os << (i < required_positionals_ ? " " + positionals_[i].first : " [" + positionals_[i].first + "]");
  if (!specs_.empty()) os << " [options]";
  os << "\n\n" << summary_ << "\n";
  if (!positionals_.empty()) {
    os << "\narguments:\n";
    for (const auto& [name, help] : positionals_) os << "  " << name << "\n      " << help << "\n";
  }
  os << "\noptions:\n";
  for (const Spec& s : specs_) {
    os << "  --" << s.name << (s.takes_value ? " " + s.value_name : "") << "\n      " << s.help;
    if (s.default_value) os << " (default: " << *s.default_value << ")";
    os << "\n";
  }
  os << "  --quiet\n      print nothing but errors\n"
        "  --progress\n      report progress on stderr even when it is not a terminal (it is shown on a terminal)\n"
        "  --help\n      print this help and exit\n";
  if (!epilog_.empty()) os << "\n" << epilog_ << "\n";
  return os.str();
}

bool Options::parse(int argc, char** argv) {
  std::size_t next_positional = 0;
  auto fail = [&](const std::string& message) {
    std::cerr << "grassfire " << command_ << ": " << message << "\n\n" << usage();
    exit_code_ = 2;
    return false;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage();
      exit_code_ = 0;
      return false;
    }
    if (a.rfind("--", 0) == 0 && a.size() > 2) {
      std::string name = a.substr(2), value;
      const std::size_t eq = name.find('=');
      const bool inline_value = eq != std::string::npos;
      if (inline_value) {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
      }
      if ((name == "quiet" || name == "progress") && !inline_value) {  // every command's switches
        values_[name] = "";
        continue;
      }
      const Spec* s = find(name);
      if (!s) return fail("unknown option --" + name);
      if (!s->takes_value) {
        if (inline_value) return fail("option --" + name + " takes no value");
        values_[name] = "";
        continue;
      }
      if (!inline_value) {
        if (i + 1 >= argc) return fail("option --" + name + " needs a value (" + s->value_name + ")");
        value = argv[++i];
      }
      values_[name] = value;
      continue;
    }
    if (next_positional >= positionals_.size()) return fail("unexpected argument '" + a + "'");
    args_[positionals_[next_positional++].first] = a;
  }
  if (next_positional < required_positionals_)
    return fail("missing argument " + positionals_[next_positional].first);
  if (has("quiet") && has("progress")) return fail("--quiet and --progress exclude each other");
  set_verbosity(has("quiet") ? Verbosity::Quiet : has("progress") ? Verbosity::Progress : Verbosity::Auto);
  return true;
}

const std::string& Options::arg(const std::string& name) const { return args_.at(name); }

bool Options::has(const std::string& name) const { return values_.count(name) > 0; }

std::string Options::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it != values_.end()) return it->second;
  const Spec* s = find(name);
  if (s && s->default_value) return *s->default_value;
  throw std::invalid_argument("option --" + name + " is required");
}

long Options::get_long(const std::string& name, long min_value, long max_value) const {
  const std::string v = get(name);
  char* end = nullptr;
  errno = 0;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || errno != 0 || x < min_value || x > max_value)
    throw std::invalid_argument("option --" + name + " must be an integer in [" + std::to_string(min_value) + ", " +
                                std::to_string(max_value) + "], got '" + v + "'");
  return x;
}

double Options::get_double(const std::string& name) const {
  const std::string v = get(name);
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x))
    throw std::invalid_argument("option --" + name + " must be a finite number, got '" + v + "'");
  return x;
}

void add_image_options(Options& opt) {
  opt.option("connectivity", "4|8", "image shapes: foreground pixels touching at a corner are joined (8) or not (4)",
             "8")
      .option("contour", "C", "image shapes: pixel (the exact pixel boundary) or marching-squares", "pixel")
      .option("foreground", "F", "image shapes: auto (the pixels unlike the image border; opaque ones if the image "
                                 "has transparency), dark, light or opaque", "auto")
      .option("threshold", "T", "image shapes: gray levels below T (0..255) are dark", "128")
      .flag("largest", "image shapes: keep the largest foreground component instead of failing on several");
}

ImageShapeOptions image_options(const Options& opt) {
  std::map<std::string, std::string> named;
  for (const char* name : {"connectivity", "contour", "foreground", "threshold"}) named[name] = opt.get(name);
  named["largest"] = opt.has("largest") ? "true" : "false";
  return parse_image_shape_options(named);
}

void add_repair_options(Options& opt) {
  opt.flag("repair", "a mesh that does not bound a solid (self-intersecting, non-manifold, open, overlapping shells)\n"
                     "is repaired first: duplicates welded, or holes filled, or else an alpha wrap (CGAL Alpha_wrap_3);\n"
                     "the report gives the defects, the method and the Hausdorff distance to the input")
      .option("repair-alpha", "A", "the alpha wrap's alpha, in the mesh's units (default: 1/50 of the bounding box "
                                   "diagonal; smaller follows concavities closer, with more triangles)")
      .option("repair-offset", "D", "the alpha wrap's offset (default: 1/300 of the bounding box diagonal)");
}

MeshRepairOptions repair_options(const Options& opt) {
  auto given = [&](const char* name) { return opt.has(name) ? std::optional<double>(opt.get_double(name)) : std::nullopt; };
  return mesh_repair_options(opt.has("repair"), given("repair-alpha"), given("repair-offset"));
}

}  // namespace grassfire::cli
