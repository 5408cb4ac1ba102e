/* sl_platform: what the viewer and the framework need from the operating
 * system, in one place, so the rest stays portable C11: a clock, file times
 * (shader hot reload polls them: no inotify, works on every system and on
 * network and container file systems), real paths, the program's own folder,
 * loadable modules and sleeping. POSIX (Linux, macOS) and Windows.
 * The grader's sandbox is Linux-only and lives in grader/. */
#ifndef SL_PLATFORM_H
#define SL_PLATFORM_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Seconds on a monotonic clock (differences only). */
double sl_platform_seconds(void);
void sl_platform_sleep(double seconds);
/* The file's modification time in nanoseconds; false if it cannot be read. */
bool sl_platform_file_time(const char *path, long long *nanoseconds);
/* A regular file exists at path. */
bool sl_platform_is_file(const char *path);
/* The absolute path with links and "." / ".." resolved (the file must exist). */
bool sl_platform_real_path(const char *path, char *out, size_t out_size);
/* The folder of the running program; false where it cannot be told. */
bool sl_platform_executable_dir(char *out, size_t out_size);
/* A loadable module (.so, .dylib, .dll): NULL with the reason in err. */
void *sl_platform_module_open(const char *path, char *err, size_t err_size);
/* A function the module exports, or NULL. */
void (*sl_platform_module_function(void *module, const char *name))(void);

/* A shell-style pattern ('*' any run of characters, '?' one) matches the
 * whole name: fnmatch() without its flags, which Windows lacks. */
bool sl_platform_match(const char *pattern, const char *name);

#ifdef __cplusplus
}
#endif
#endif
