#include "core/image_io/image_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <system_error>

namespace wt {

std::string image_module_path() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path dir = ec ? std::filesystem::path(".") : exe.parent_path();
    return (dir / "libwavetrace_image_io.so").string();
}

namespace {

const WtImageModuleApi* load_module(std::string& error) {
    const std::string path = image_module_path();
    const std::string what = "cannot load the image I/O module " + path +
                             " (it reads every image and writes those but EXR and PNG, and belongs next to the wavetrace executable): ";
    // Lazy binding, as for a library the executable links: resolving every function of the
    // ~260 libraries at once (RTLD_NOW) cost a tiny render 20 % more CPU time.
    void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
        const char* reason = dlerror();
        error = what + (reason ? reason : "unknown error");
        return nullptr;
    }
    auto entry = reinterpret_cast<WtImageModuleEntryPoint>(dlsym(handle, WT_IMAGE_MODULE_ENTRY_POINT));
    const WtImageModuleApi* api = entry ? entry() : nullptr;
    if (!api) {
        error = what + "it has no " WT_IMAGE_MODULE_ENTRY_POINT;
    } else if (api->abi_version != WT_IMAGE_MODULE_ABI_VERSION) {
        error = what + "it is of interface version " + std::to_string(api->abi_version) + ", this program needs " +
                std::to_string(int(WT_IMAGE_MODULE_ABI_VERSION)) + " (a module from another build)";
    } else {
        return api;  // the handle stays open for the life of the process
    }
    dlclose(handle);
    return nullptr;
}

}  // namespace

const WtImageModuleApi& image_module() {
    static std::mutex mutex;
    static const WtImageModuleApi* api = nullptr;
    std::lock_guard<std::mutex> lock(mutex);
    if (!api) {
        std::string error;
        api = load_module(error);
        if (!api) throw ImageError(error);
    }
    return *api;
}

}  // namespace wt
