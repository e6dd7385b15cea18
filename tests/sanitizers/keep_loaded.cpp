// Preloaded into the sanitizer run's test processes (tests/sanitizers/
// CMakeLists.txt): dlclose does nothing, so the Vulkan driver and layers the
// loader unloads at vkDestroyInstance stay mapped until exit. LeakSanitizer
// reports at exit; without this, every frame of a driver's leak reads
// "<unknown module>" and no suppression can name the library it came from.
extern "C" int dlclose(void*) { return 0; }
