/*
 * ef_api.h - EF_API, the mark of an exported function.
 *
 * libedgeflag is built with -fvisibility=hidden: a function is visible to a
 * program linking libedgeflag.so only when its declaration in a public header
 * (include/edgeflag/) carries EF_API.  So the shared library's dynamic symbol
 * table is exactly the documented API (tests/install_check.sh compares the two),
 * and the model's internals (ef_in_*, ef_plot_*, ...) cannot become an API by
 * accident.  The static library keeps every symbol, as static libraries do.
 */
#ifndef EF_API_H
#define EF_API_H

#ifndef EF_API
#if defined(__GNUC__) && __GNUC__ >= 4
#define EF_API __attribute__((visibility("default")))
#else
#define EF_API
#endif
#endif

#endif /* EF_API_H */
