// One validated context per test process, destroyed at exit so that leaks are reported too.
#include "support/gpu_test_context.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace glint::test {

namespace {

// Owns the context for the process lifetime. Its destructor runs among the static
// destructors after main returns: it destroys the context, during which the layer reports
// objects that tests leaked, then turns any error ever seen into a failing exit status.
struct SharedContext {
    gpu::Context context;
    uint32_t checkedErrors = 0; // errors already reported through takeValidationErrors
    size_t checkedMessages = 0;

    SharedContext() {
        gpu::ContextOptions options;
        options.validation = true;
        options.synchronizationValidation = true;
        context = gpu::createContext(options);
    }

    ~SharedContext() {
        gpu::destroyContext(context);
        const uint32_t errors = context.validation->errors.load();
        if (errors == 0) return;
        // The messages themselves went to stderr as they arrived; a summary by message id
        // keeps a wall of leak reports after a failed test readable.
        std::map<std::string, int> byId;
        for (const std::string& message : gpu::validationMessages(*context.validation)) {
            if (message.rfind("error: ", 0) == 0) ++byId[message.substr(7, message.find(':', 7) - 7)];
        }
        std::fprintf(stderr,
                     "glint tests: %u Vulkan validation error(s) in this process, exiting with status 1:\n",
                     errors);
        for (const auto& [id, count] : byId) std::fprintf(stderr, "  %dx %s\n", count, id.c_str());
        std::fflush(stderr);
        // _Exit rather than exit: we are already inside exit's static destruction.
        std::_Exit(1);
    }

    SharedContext(const SharedContext&) = delete;
    SharedContext& operator=(const SharedContext&) = delete;
};

std::mutex g_mutex;
SharedContext* g_shared = nullptr;

} // namespace

gpu::Context& testContext() {
    // A function-local static is destroyed in reverse order of construction, i.e. before
    // Catch's own statics, which were constructed before any test ran.
    static SharedContext shared;
    {
        std::lock_guard<std::mutex> lock(g_mutex);
        g_shared = &shared;
    }
    return shared.context;
}

ValidationCheck takeValidationErrors() {
    std::lock_guard<std::mutex> lock(g_mutex);
    ValidationCheck check;
    if (!g_shared || !g_shared->context.validation) return check;
    gpu::ValidationStats& stats = *g_shared->context.validation;
    const uint32_t errors = stats.errors.load();
    check.newErrors = errors - g_shared->checkedErrors;
    g_shared->checkedErrors = errors;
    const std::vector<std::string> messages = gpu::validationMessages(stats, g_shared->checkedMessages);
    g_shared->checkedMessages += messages.size();
    for (const std::string& message : messages) check.messages += message + "\n";
    return check;
}

bool skipsForbidden() {
    const char* value = std::getenv("GLINT_FORBID_SKIPS");
    return value && std::string(value) != "0" && std::string(value) != "";
}

} // namespace glint::test
