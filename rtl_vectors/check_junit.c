/*
 * check_junit.c - `edgeflag check --junit FILE`: the comparison as JUnit XML
 * for CI (Jenkins, GitLab, GitHub annotators all read this shape): one
 * <testcase> per interface of each pair of files, a <failure> holding the
 * mismatch lines that were reported (or saying that the dump is missing), a
 * <skipped/> for an interface --interfaces or --allow-missing left out, an
 * <error> for an input that could not be read.  The suite is named by
 * --name, else by EXPECTED's base name and the vectors' seed.  File names and messages are escaped so the document is always
 * well-formed XML 1.0: markup characters as entities, valid UTF-8 as is,
 * control characters and stray bytes (which XML 1.0 cannot hold at all) as
 * the text "\xNN".  Times are integer nanoseconds printed as seconds with
 * three decimals (no floating point).  The caller gives the FILE (the
 * command writes it atomically).
 */
#include "check_internal.h"
#include "ef_fixed.h" /* ef_utf8_len */

#include <errno.h>
#include <inttypes.h>
#include <string.h>
#include <time.h>

uint64_t chk_now_ns(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0)
        return 0;
    return (uint64_t)ts.tv_sec * UINT64_C(1000000000) + (uint64_t)ts.tv_nsec;
}

/* s escaped for XML; newlines kept in text, written as &#10; in attributes. */
static void esc(FILE *f, const char *str, int attr)
{
    const unsigned char *s = (const unsigned char *)(str ? str : "");
    size_t n = strlen((const char *)s);
    for (size_t i = 0; i < n;) {
        unsigned char c = s[i];
        size_t len;
        if (c == '&')
            fputs("&amp;", f);
        else if (c == '<')
            fputs("&lt;", f);
        else if (c == '>')
            fputs("&gt;", f);
        else if (c == '"')
            fputs("&quot;", f);
        else if (c == '\'')
            fputs("&apos;", f);
        else if (c == '\n')
            fputs(attr ? "&#10;" : "\n", f);
        else if (c == '\t')
            fputs(attr ? "&#9;" : "\t", f);
        else if (c >= 0x20 && c < 0x7f)
            fputc(c, f);
        else if (c >= 0x80 && (len = ef_utf8_len(s + i, n - i)) != 0) {
            fwrite(s + i, 1, len, f);
            i += len;
            continue;
        } else
            fprintf(f, "\\x%02x", c);
        i++;
    }
}

static void put_time(FILE *f, uint64_t ns)
{
    const uint64_t ms = ns / 1000000u;
    fprintf(f, "%" PRIu64 ".%03" PRIu64, ms / 1000u, ms % 1000u);
}

/* --name, else "BASE seed S" (BASE: EXPECTED's last path component). */
static void suite_name(FILE *f, const chk_run *r)
{
    if (r->a->name) {
        esc(f, r->a->name, 1);
        return;
    }
    const char *e = r->a->expected;
    size_t n = strlen(e);
    while (n > 1 && e[n - 1] == '/')
        n--;
    size_t b = n;
    while (b > 0 && e[b - 1] != '/')
        b--;
    char base[512];
    snprintf(base, sizeof base, "%.*s", (int)(n - b < 500 ? n - b : 500), e + b);
    esc(f, base, 1);
    if (r->seed)
        fprintf(f, " seed %" PRIu64, r->seed);
}

static void write_cases(FILE *f, const chk_run *r)
{
    uint64_t failures = 0, errors = 0, skipped = 0, ns = 0;
    for (size_t k = 0; k < r->ncases; k++) {
        failures += !r->cases[k].error && (r->cases[k].mismatches || r->cases[k].missing);
        errors += r->cases[k].error != NULL;
        skipped += r->cases[k].skipped;
        ns += r->cases[k].ns;
    }
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"", f);
    suite_name(f, r);
    fprintf(f, "\" tests=\"%zu\" failures=\"%" PRIu64 "\" errors=\"%" PRIu64 "\" skipped=\"%" PRIu64 "\" time=\"",
            r->ncases, failures, errors, skipped);
    put_time(f, ns);
    fputs("\">\n  <testsuite name=\"", f);
    suite_name(f, r);
    fprintf(f, "\" tests=\"%zu\" failures=\"%" PRIu64 "\" errors=\"%" PRIu64 "\" skipped=\"%" PRIu64 "\" time=\"",
            r->ncases, failures, errors, skipped);
    put_time(f, ns);
    fputs("\">\n", f);
    for (size_t k = 0; k < r->ncases; k++) {
        const chk_case *c = &r->cases[k];
        fputs("    <testcase classname=\"", f);
        suite_name(f, r);
        fputs("\" name=\"", f);
        esc(f, c->name, 1);
        fputs(": ", f);
        esc(f, c->classname, 1);
        fputs("\" time=\"", f);
        put_time(f, c->ns);
        if (c->skipped) {
            fputs("\">\n      <skipped message=\"not compared (--interfaces or --allow-missing)\"/>\n    </testcase>\n",
                  f);
        } else if (c->missing) {
            fputs("\">\n      <failure type=\"missing dump\" message=\"no dump of ", f);
            esc(f, c->name, 1);
            fputs(" in ACTUAL: a bench that does not write it cannot pass\"/>\n    </testcase>\n", f);
        } else if (c->error) {
            fputs("\">\n      <error type=\"unreadable input\" message=\"", f);
            esc(f, c->error, 1);
            fputs("\"/>\n    </testcase>\n", f);
        } else if (c->mismatches) {
            fprintf(f,
                    "\">\n      <failure type=\"mismatch\" message=\"%" PRIu64 " mismatch%s (%" PRIu64
                    " expected, %" PRIu64 " actual transactions)\">",
                    c->mismatches, c->mismatches == 1 ? "" : "es", c->expected, c->actual);
            esc(f, c->text, 0);
            fprintf(f, "(%" PRIu64 " mismatch%s in all; the lines above are those reported under --errors)\n",
                    c->mismatches, c->mismatches == 1 ? "" : "es");
            fputs("</failure>\n    </testcase>\n", f);
        } else {
            fputs("\"/>\n", f);
        }
    }
    fputs("  </testsuite>\n</testsuites>\n", f);
}

int ef_check_junit(const ef_check_result *res, FILE *f)
{
    if (!res->run) {
        errno = EINVAL;
        return -1;
    }
    errno = 0;
    write_cases(f, res->run);
    if (ferror(f)) {
        if (!errno)
            errno = EIO;
        return -1;
    }
    return 0;
}
