// Built into every target of the sanitizer build (RAYLAB_SANITIZE) only.
//
// GCC 12's sanitizer runtime (Debian 12; fixed in GCC 14 and LLVM 17) takes a
// dynamic TLS block whose address is 16 mod 4096 for one with glibc 2.19's
// header and reads the two words before it as that block's address and size.
// glibc >= 2.25 has no such header, so when a block of a dlopen'd library
// (OpenImageIO's module, loaded for JPEG, HDR and TIFF outputs) lands there
// by chance, LeakSanitizer's tracer dereferences garbage at exit ("Tracer
// caught signal 11") and the run fails without any leak. Which runs hit it
// depends on the heap's layout alone. intercept_tls_get_addr=0 stops that
// bookkeeping (google/sanitizers#1322); the environment's ASAN_OPTIONS still
// add to or override it. Weak: every object of a target that links
// raylab_warnings carries a copy (the runtime's own default is weak too).
extern "C" __attribute__((weak)) const char* __asan_default_options() {
    return "intercept_tls_get_addr=0";
}
