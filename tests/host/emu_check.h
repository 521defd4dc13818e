/*
 * emu_check.h - the checks of the programs that drive the GPIO transport
 * against an emulated chip (gpio_emu.c, gpio_cosim.c): check(ok, fmt, ...)
 * counts a check and, when it fails, counts the failure and prints "FAIL: "
 * and the message on standard error; `checks` and `failed` are the totals
 * their main() reports.  Static definitions: included by one file of a
 * program.
 */
#ifndef EF_TEST_EMU_CHECK_H
#define EF_TEST_EMU_CHECK_H

#include <stdarg.h>
#include <stdio.h>

static int checks, failed;

static void check(int ok, const char *fmt, ...)
{
    va_list ap;
    checks++;
    if (ok)
        return;
    failed++;
    fprintf(stderr, "FAIL: ");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

#endif /* EF_TEST_EMU_CHECK_H */
