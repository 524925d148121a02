#include "testbed/app/plugins.h"

#include <dlfcn.h>
#include <link.h>

#include <filesystem>
#include <set>

#include "testbed/core/error.h"
#include "testbed/gl/shader_library.h"
#include "testbed/technique/plugin.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

// Ids whose output files would collide with compare's own (groundtruth.png, grid.png,
// metrics.json) or that mean something else on the command line (--techniques all).
const std::set<std::string, std::less<>> kReservedIds = {"all",         "area",    "grid",
                                                         "groundtruth", "metrics", "raycast"};

void checkTechnique(const TechniqueInfo& info, const std::set<std::string>& earlier, const std::string& where) {
  if (const std::string problem = techniqueProblem(info); !problem.empty()) throw InputError(where + ": " + problem);
  const std::string technique = where + ": technique '" + info.id + "'";
  if (kReservedIds.count(info.id)) throw InputError(technique + ": the id is reserved by the testbed");
  if (isTechniqueRegistered(info.id) || earlier.count(info.id))
    throw InputError(technique + ": the id is already registered");
}

// dlerror() starts with the file name; the caller names the path already.
std::string loaderMessage(const std::string& file) {
  const char* error = dlerror();
  std::string text = error ? error : "unknown dlopen error";
  if (text.rfind(file + ": ", 0) == 0) text.erase(0, file.size() + 2);
  return text;
}

// Whether `address` is where a function symbol of a loaded library starts, by the ELF
// symbol table: a data symbol under an entry point's name is refused before it is called
// (calling it would jump into data and crash).
bool isFunctionSymbol(void* address) {
  Dl_info info{};
  void* entry = nullptr;
  if (!dladdr1(address, &info, &entry, RTLD_DL_SYMENT) || !entry) return false;
  const int type = ELF64_ST_TYPE(static_cast<const ElfW(Sym)*>(entry)->st_info);  // the same macro for ELF32
  return info.dli_saddr == address && (type == STT_FUNC || type == STT_GNU_IFUNC);
}

void loadPlugin(const std::string& path, std::set<void*>& loaded) {
  const std::string where = "--plugin " + path;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(where + ": no such file");
  if (!fs::is_regular_file(path, ec)) throw InputError(where + ": not a file");
  // A name without '/' would make dlopen search the library path instead of this file.
  const std::string file = fs::absolute(path).lexically_normal().string();

  std::vector<RegisteredTechnique> techniques;
  void* handle = nullptr;
  {
    StaticRegistrationCapture capture(techniques);  // TESTBED_REGISTER_TECHNIQUE in the plugin
    takeShaderConflicts();  // only this library's count
    dlerror();
    // RTLD_NOW: a plugin built against another testbed fails here on an unresolved symbol
    // instead of later, mid-frame. The library stays loaded for the process's lifetime:
    // the registry keeps pointers to its TechniqueInfo and its factories.
    handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (!handle) throw InputError(where + ": cannot load it as a shared library: " + loaderMessage(file));
  if (!loaded.insert(handle).second) return;  // the same file twice (another path, a link)
  if (const auto clashes = takeShaderConflicts(); !clashes.empty())
    throw InputError(where + ": shader '" + clashes.front() +
                     "' is already embedded with other text; keep a plugin's shaders in a folder of its own");

  auto* version = reinterpret_cast<testbed_plugin_api_version_fn*>(dlsym(handle, "testbed_plugin_api_version"));
  auto* entry = reinterpret_cast<testbed_register_plugin_fn*>(dlsym(handle, "testbed_register_plugin"));
  if (!entry || !version)
    throw InputError(where + ": not a testbed plugin: it exports no " +
                     (entry ? "testbed_plugin_api_version" : "testbed_register_plugin") +
                     " function (define both with TESTBED_PLUGIN from testbed/technique/plugin.h)");
  for (const auto& [name, address] : {std::pair<const char*, void*>{"testbed_plugin_api_version", reinterpret_cast<void*>(version)},
                                      {"testbed_register_plugin", reinterpret_cast<void*>(entry)}})
    if (!isFunctionSymbol(address))
      throw InputError(where + ": not a testbed plugin: " + name +
                       " is not a function (define both with TESTBED_PLUGIN from testbed/technique/plugin.h)");
  if (const int v = version(); v != TESTBED_PLUGIN_API_VERSION)
    throw InputError(where + ": built for plugin API version " + std::to_string(v) + ", this testbed loads version " +
                     std::to_string(TESTBED_PLUGIN_API_VERSION) + ": rebuild it against this testbed");

  PluginRegistrar registrar;
  try {
    entry(registrar);
  } catch (const std::exception& error) {
    throw InputError(where + ": its registration function failed: " + error.what());
  }
  techniques.insert(techniques.end(), registrar.added().begin(), registrar.added().end());
  if (techniques.empty()) throw InputError(where + ": registers no technique");

  std::set<std::string> ids;
  for (const auto& t : techniques) {
    checkTechnique(*t.info, ids, where);
    ids.insert(t.info->id);
  }
  for (auto& t : techniques) addTechnique(std::move(t));
}

}  // namespace

void loadPlugins(const std::vector<std::string>& paths) {
  static std::set<void*> loaded;
  for (const auto& path : paths) loadPlugin(path, loaded);
}

}  // namespace testbed
