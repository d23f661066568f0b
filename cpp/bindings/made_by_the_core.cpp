// The classes whose instances only the core makes (results, reports, records): none has a public constructor.
// Calling one raises TypeError naming what makes one (pybind11's own message names nothing), and its __init__ takes
// (*args, **kwargs), what the call accepts before it raises, so that inspect.signature works on it as on every other
// public class (add_text_signatures reads the signature from that __init__).
#include "bindings.hpp"

#include <pybind11/pybind11.h>

#include <string>

namespace py = pybind11;

namespace rigiddyn::bindings {
namespace {

struct MadeBy {
  const char* name;     // the class in the module
  const char* made_by;  // what makes its instances
};

constexpr MadeBy made_by_the_core_table[] = {
    {"BatchSceneResult", "simulate_batch returns one"},
    {"BodyRecords", "SceneResult.body and BatchSceneResult.body return one"},
    {"ElementField", "each element class lists its fields (e.g. SpringDamper.fields)"},
    {"GlobalError", "simulate(..., error=True) returns one as result.error"},
    {"InertiaReport", "inertia_report and SpatialInertia.report return one"},
    {"SceneFrame", "its static constructors make one (SceneFrame.rotating, ...)"},
    {"SceneResult", "simulate(scene, ...) returns one"},
    {"ToleranceChoice", "simulate(..., tolerance=...) returns one as result.choice"},
    {"TreeLink", "Scene.add_tree makes one per link (read as scene.bodies[i])"},
    {"WeldedMesh", "weld_vertices returns one"},
};

// Gives `cls` an __init__ that raises "TypeError: <name> has no public constructor: <made_by>"
void add_refusing_constructor(const py::handle& cls, const std::string& name, const std::string& made_by) {
  const std::string message = name + " has no public constructor: " + made_by;
  py::setattr(cls, "__init__",
              py::cpp_function([message](py::handle, const py::args&, const py::kwargs&) { throw py::type_error(message); },
                               py::is_method(cls), py::name("__init__"), ("Raises TypeError: " + message + ".").c_str()));
}

}  // namespace

void mark_made_by_the_core(py::module_& m) {
  for (const MadeBy& entry : made_by_the_core_table) add_refusing_constructor(m.attr(entry.name), entry.name, entry.made_by);
}

}  // namespace rigiddyn::bindings
