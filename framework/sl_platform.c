/* sl_platform: see sl_platform.h. */
#if !defined(_WIN32) && !defined(__APPLE__)
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE /* realpath */
#endif
#include "sl_platform.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#include <limits.h>
#include <stdlib.h>
#include <unistd.h>
#endif
#ifdef __APPLE__
#include <mach-o/dyld.h>
#endif

double sl_platform_seconds(void) {
#ifdef _WIN32
    LARGE_INTEGER frequency, now;
    QueryPerformanceFrequency(&frequency);
    QueryPerformanceCounter(&now);
    return (double)now.QuadPart / (double)frequency.QuadPart;
#else
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
#endif
}

void sl_platform_sleep(double seconds) {
    if (seconds <= 0) return;
#ifdef _WIN32
    Sleep((DWORD)(seconds * 1000));
#else
    struct timespec wait = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
    nanosleep(&wait, NULL);
#endif
}

bool sl_platform_file_time(const char *path, long long *nanoseconds) {
#ifdef _WIN32
    struct __stat64 st;
    if (_stat64(path, &st) != 0) return false;
    *nanoseconds = (long long)st.st_mtime * 1000000000LL;
#elif defined(__APPLE__)
    struct stat st;
    if (stat(path, &st) != 0) return false;
    *nanoseconds = (long long)st.st_mtimespec.tv_sec * 1000000000LL + st.st_mtimespec.tv_nsec;
#else
    struct stat st;
    if (stat(path, &st) != 0) return false;
    *nanoseconds = (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec;
#endif
    return true;
}

bool sl_platform_is_file(const char *path) {
#ifdef _WIN32
    struct __stat64 st;
    return _stat64(path, &st) == 0 && (st.st_mode & _S_IFREG);
#else
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
#endif
}

bool sl_platform_real_path(const char *path, char *out, size_t out_size) {
#ifdef _WIN32
    char full[MAX_PATH];
    if (!_fullpath(full, path, sizeof full)) return false;
    if (GetFileAttributesA(full) == INVALID_FILE_ATTRIBUTES) return false;
    for (char *c = full; *c; c++)
        if (*c == '\\') *c = '/'; /* one separator in messages and prefix checks */
    return (size_t)snprintf(out, out_size, "%s", full) < out_size;
#else
    char real[PATH_MAX];
    if (!realpath(path, real)) return false;
    return (size_t)snprintf(out, out_size, "%s", real) < out_size;
#endif
}

bool sl_platform_executable_dir(char *out, size_t out_size) {
    char path[4096];
#if defined(_WIN32)
    DWORD n = GetModuleFileNameA(NULL, path, sizeof path);
    if (n == 0 || n >= sizeof path) return false;
    path[n] = '\0';
    for (char *c = path; *c; c++)
        if (*c == '\\') *c = '/';
#elif defined(__APPLE__)
    uint32_t size = sizeof path;
    char raw[4096];
    if (_NSGetExecutablePath(raw, &size) != 0 || !realpath(raw, path)) return false;
#else
    ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
    if (n <= 0) return false;
    path[n] = '\0';
#endif
    char *slash = strrchr(path, '/');
    if (!slash) return false;
    *slash = '\0';
    return (size_t)snprintf(out, out_size, "%s", path) < out_size;
}

void *sl_platform_module_open(const char *path, char *err, size_t err_size) {
#ifdef _WIN32
    HMODULE module = LoadLibraryA(path);
    if (!module && err && err_size) snprintf(err, err_size, "LoadLibrary failed (error %lu)", (unsigned long)GetLastError());
    return (void *)module;
#else
    void *module = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!module && err && err_size) {
        const char *why = dlerror();
        snprintf(err, err_size, "%s", why ? why : "unknown reason");
    }
    return module;
#endif
}

void (*sl_platform_module_function(void *module, const char *name))(void) {
    void (*function)(void) = NULL;
#ifdef _WIN32
    FARPROC p = GetProcAddress((HMODULE)module, name);
    memcpy(&function, &p, sizeof function);
#else
    /* POSIX: dlsym's object pointer converts to a function pointer through memcpy. */
    void *p = dlsym(module, name);
    memcpy(&function, &p, sizeof function);
#endif
    return function;
}

bool sl_platform_match(const char *pattern, const char *name) {
    /* the last '*' seen and where the name stood then: backtrack there on a mismatch */
    const char *star = NULL, *resume = NULL;
    while (*name) {
        if (*pattern == '*') {
            star = pattern++;
            resume = name;
        } else if (*pattern == '?' || *pattern == *name) {
            pattern++;
            name++;
        } else if (star) {
            pattern = star + 1;
            name = ++resume;
        } else {
            return false;
        }
    }
    while (*pattern == '*') pattern++;
    return *pattern == '\0';
}
