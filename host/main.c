/*
 * main.c - `edgeflag-host`: drives an edgeflag board (docs/board.md section 7
 * is its user documentation).  list / stream / verify / bench / identify; everything
 * protocol-shaped lives in host_link.c and bench_link.c, everything
 * link-shaped in the transports.
 */
#include <errno.h>
#include <getopt.h>
#include <inttypes.h>
#include <libgen.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "atomic_file.h"
#include "bench_link.h"
#include "check_files.h"
#include "ef_vec_read.h"
#include "image_write.h"
#include "dut_rtl.h"
#include "edgeflag.h"
#include "ef_check.h"
#include "ef_trace.h"
#include "host_link.h"
#include "parse.h"
#include "transport.h"

static const ef_transport_ops *const TRANSPORTS[] = { &ef_transport_usb,  &ef_transport_gpio,   &ef_transport_sim,
                                                      &ef_transport_null, &ef_transport_socket, &ef_transport_serial };
/* the transports of real boards that `list` and `auto` probe (GPIO for auto only with --chip) */
static const ef_transport_ops *const PROBED[] = { &ef_transport_usb, &ef_transport_gpio, &ef_transport_serial };
#define NPROBED (sizeof PROBED / sizeof PROBED[0])
#define NTRANSPORTS (sizeof TRANSPORTS / sizeof TRANSPORTS[0])

typedef struct args {
    const char *cmd, *vectors, *transport, *results, *junit, *diff_image, *interfaces, *save_frame, *save;
    ef_util_format diff_fmt;
    int32_t errors; /* -1: check's default */
    long digest;    /* -1: not given (digest mode on a serial line, full records elsewhere) */
    unsigned digest_fetch;
    ef_host_opts link;
    int resume, quiet, json, transactions;
    unsigned frame_cmds;
    uint64_t bench_bytes;
} args;

static void usage(FILE *f)
{
    fputs("usage: edgeflag-host list [--json] [--chip NAME] [--vid-pid VVVV:PPPP]\n"
          "       edgeflag-host stream VECTORS.bin [LINK OPTIONS] [--results DIR] [--resume]\n"
          "       edgeflag-host verify VECTORS.bin [LINK OPTIONS] [--results DIR] [--resume]\n"
          "                     [--interfaces LIST] [--junit FILE] [--diff-image FILE.png] [--errors N]\n"
          "                     [--transactions]\n"
          "       edgeflag-host bench [LINK OPTIONS] [--mib N]\n"
          "       edgeflag-host identify [LINK OPTIONS] [--save FILE] [--json]\n"
          "       edgeflag-host --version | --help\n"
          "\n"
          "Streams an edgeflag vectors.bin's command stream to a board (docs/board.md), collects\n"
          "the board's results as vectors.actual.bin and (verify) checks them as `edgeflag check`.\n"
          "\n"
          "link options:\n"
          "  --transport T        usb, gpio, serial, sim, null, socket or auto (default auto: the one board present;\n"
          "                       none or several is an error, never the simulated board)\n"
          "  --device SEL         usb: SERIAL, BUS:DEV or #INDEX (as `list` prints)\n"
          "  --connect ADDR       socket: unix:PATH or tcp:HOST:PORT (docs/board.md 5.5)\n"
          "  --port TTY           serial: the board's tty (/dev/ttyUSB0; docs/board-serial.md)\n"
          "  --baud N             serial: line speed (default 3000000)\n"
          "  --vid-pid V:P        usb: vendor and product id in hex (default 1209:0001)\n"
          "  --transfer-size N    usb: bytes per bulk transfer     --in-flight N  transfers in flight\n"
          "  --chip NAME          gpio: chip (gpiochip0 or /dev/gpiochip0)\n"
          "  --lines MAP          gpio: line map, docs/board-gpio.md\n"
          "  --timeout MS         no progress for MS ms: retransmit; 4 times: give up (default 2000)\n"
          "  --sim-state DIR      sim: keep the simulated board's state in DIR (it outlives the process)\n"
          "  --sim-faults LIST    sim: play faults, KIND=N,... (docs/board.md section 6)\n"
          "  --sim-dut model|rtl  sim: the board's DUT, the C model (default) or the Verilated RTL\n"
          "                       (built in with make host-rtl; see --version)\n"
          "other options:\n"
          "  --results DIR        where results and resume state go (default: VECTORS.bin's folder/board)\n"
          "  --resume             continue an interrupted run from its last acknowledged frame\n"
          "  --frame-cmds N       commands per DATA frame (default 5041, 65533 bytes)\n"
          "  --interfaces LIST    verify: interfaces to ask back and check (must include pix;\n"
          "                       default pix and every internal one the file and the board have)\n"
          "  --junit FILE, --diff-image FILE.png, --errors N, --transactions: as edgeflag check\n"
          "  --save-frame FILE.png  verify: the board's pix results as an image\n"
          "  --digest N|off       verify: the board returns a CRC-32 per N transactions, differing\n"
          "                       windows are fetched whole (docs/board.md 4.5; default 1024 on a\n"
          "                       serial line, off elsewhere)   --digest-fetch K  windows fetched (16)\n"
          "  --mib N              bench: MiB per throughput test (default 64)\n"
          "  --save FILE          identify: write the board's 48-byte identify record to FILE (atomically),\n"
          "                       the file `edgeflag gen --dut-file FILE` fits cases to\n"
          "  --quiet              no progress bar and no summary     --json  summary as JSON on stdout\n"
          "\n"
          "exit codes: 0 ok, 1 verify found mismatches, 2 usage, 3 bad vectors file, 4 results not\n"
          "written, 5 link lost (unplugged or not answering: --resume continues), 6 board error or\n"
          "protocol violation, 7 no board or several, 8 permission denied, 70 internal error.\n",
          f);
}

static int usage_error(const char *fmt, const char *what)
{
    fputs("edgeflag-host: ", stderr);
    fprintf(stderr, fmt, what);
    fputs("\n(edgeflag-host --help shows the usage)\n", stderr);
    return EF_HX_USAGE;
}

static const ef_transport_ops *find_transport(const char *name)
{
    for (size_t i = 0; i < NTRANSPORTS; i++)
        if (strcmp(TRANSPORTS[i]->name, name) == 0)
            return TRANSPORTS[i];
    return NULL;
}

static int parse(int argc, char **argv, args *a)
{
    enum {
        O_TRANSPORT = 256,
        O_DEVICE,
        O_VIDPID,
        O_TSIZE,
        O_INFLIGHT,
        O_CHIP,
        O_LINES,
        O_TIMEOUT,
        O_SIMSTATE,
        O_SIMFAULTS,
        O_CONNECT,
        O_RESULTS,
        O_RESUME,
        O_FRAMECMDS,
        O_IFACES,
        O_JUNIT,
        O_DIFF,
        O_ERRORS,
        O_TRANS,
        O_MIB,
        O_QUIET,
        O_JSON,
        O_HELP,
        O_SIMDUT,
        O_PORT,
        O_BAUD,
        O_DIGEST,
        O_DIGESTFETCH,
        O_SAVEFRAME,
        O_SAVE
    };
    static const struct option opts[] = { { "transport", required_argument, 0, O_TRANSPORT },
                                          { "device", required_argument, 0, O_DEVICE },
                                          { "vid-pid", required_argument, 0, O_VIDPID },
                                          { "transfer-size", required_argument, 0, O_TSIZE },
                                          { "in-flight", required_argument, 0, O_INFLIGHT },
                                          { "chip", required_argument, 0, O_CHIP },
                                          { "lines", required_argument, 0, O_LINES },
                                          { "timeout", required_argument, 0, O_TIMEOUT },
                                          { "sim-state", required_argument, 0, O_SIMSTATE },
                                          { "sim-faults", required_argument, 0, O_SIMFAULTS },
                                          { "sim-dut", required_argument, 0, O_SIMDUT },
                                          { "connect", required_argument, 0, O_CONNECT },
                                          { "port", required_argument, 0, O_PORT },
                                          { "baud", required_argument, 0, O_BAUD },
                                          { "digest", required_argument, 0, O_DIGEST },
                                          { "digest-fetch", required_argument, 0, O_DIGESTFETCH },
                                          { "save-frame", required_argument, 0, O_SAVEFRAME },
                                          { "save", required_argument, 0, O_SAVE },
                                          { "results", required_argument, 0, O_RESULTS },
                                          { "resume", no_argument, 0, O_RESUME },
                                          { "frame-cmds", required_argument, 0, O_FRAMECMDS },
                                          { "interfaces", required_argument, 0, O_IFACES },
                                          { "junit", required_argument, 0, O_JUNIT },
                                          { "diff-image", required_argument, 0, O_DIFF },
                                          { "errors", required_argument, 0, O_ERRORS },
                                          { "transactions", no_argument, 0, O_TRANS },
                                          { "mib", required_argument, 0, O_MIB },
                                          { "quiet", no_argument, 0, O_QUIET },
                                          { "json", no_argument, 0, O_JSON },
                                          { "help", no_argument, 0, O_HELP },
                                          { 0, 0, 0, 0 } };
    int32_t v; /* ef_util_parse_int: digits only, within the bounds (util/parse.c) */
    opterr = 0;
    optind = 1;
    int c;
    while ((c = getopt_long(argc, argv, ":h", opts, NULL)) != -1) {
        switch (c) {
        case O_TRANSPORT:
            if (strcmp(optarg, "auto") != 0 && !find_transport(optarg))
                return usage_error("--transport must be usb, gpio, serial, sim, null, socket or auto, not '%s'",
                                   optarg);
            a->transport = optarg;
            break;
        case O_DEVICE: a->link.device = optarg; break;
        case O_VIDPID: {
            unsigned vid, pid;
            char extra;
            if (sscanf(optarg, "%4x:%4x%c", &vid, &pid, &extra) != 2)
                return usage_error("--vid-pid must be VVVV:PPPP in hex, not '%s'", optarg);
            a->link.vid = (uint16_t)vid, a->link.pid = (uint16_t)pid;
            break;
        }
        case O_TSIZE:
            if (!ef_util_parse_int(optarg, 512, 1 << 24, &v) || v % 512)
                return usage_error("--transfer-size must be a multiple of 512 up to 16 MiB, not '%s'", optarg);
            a->link.transfer_size = (unsigned)v;
            break;
        case O_INFLIGHT:
            if (!ef_util_parse_int(optarg, 1, 256, &v))
                return usage_error("--in-flight must be 1..256, not '%s'", optarg);
            a->link.in_flight = (unsigned)v;
            break;
        case O_CHIP: a->link.chip = optarg; break;
        case O_LINES: a->link.lines = optarg; break;
        case O_TIMEOUT:
            if (!ef_util_parse_int(optarg, 1, 3600000, &v))
                return usage_error("--timeout must be 1..3600000 ms, not '%s'", optarg);
            a->link.timeout_ms = (int)v;
            break;
        case O_SIMSTATE: a->link.sim_state = optarg; break;
        case O_SIMFAULTS: a->link.sim_faults = optarg; break;
        case O_SIMDUT:
            if (strcmp(optarg, "model") == 0)
                ef_transport_sim_select_dut(EF_SIM_DUT_MODEL);
            else if (strcmp(optarg, "rtl") == 0)
                ef_transport_sim_select_dut(EF_SIM_DUT_RTL);
            else
                return usage_error("--sim-dut must be model or rtl, not '%s'", optarg);
            break;
        case O_CONNECT: a->link.connect = optarg; break;
        case O_PORT: a->link.port = optarg; break;
        case O_BAUD: /* any rate the driver takes (docs/board-serial.md section 2) */
            a->link.baud = ef_util_parse_int(optarg, 50, 100000000, &v) ? (unsigned)v : 0;
            if (!a->link.baud)
                return usage_error("--baud must be 50..100000000, not '%s'", optarg);
            break;
        case O_DIGEST:
            if (strcmp(optarg, "off") == 0)
                v = 0;
            else if (!ef_util_parse_int(optarg, 1, 1 << 24, &v))
                return usage_error("--digest must be 1..16777216 transactions a window or off, not '%s'", optarg);
            a->digest = v;
            break;
        case O_DIGESTFETCH:
            if (!ef_util_parse_int(optarg, 1, EF_PROTO_SELECT_MAX, &v))
                return usage_error("--digest-fetch must be 1..1024 windows, not '%s'", optarg);
            a->digest_fetch = (unsigned)v;
            break;
        case O_SAVEFRAME:
            if (ef_util_format_from_path(optarg) != EF_UTIL_FMT_PNG || !ef_util_format_available(EF_UTIL_FMT_PNG))
                return usage_error("--save-frame needs a FILE.png (and a build with libpng), not '%s'", optarg);
            a->save_frame = optarg;
            break;
        case O_SAVE:
            if (!*optarg)
                return usage_error("--save needs a file name, not '%s'", optarg);
            a->save = optarg;
            break;
        case O_RESULTS: a->results = optarg; break;
        case O_RESUME: a->resume = 1; break;
        case O_FRAMECMDS:
            if (!ef_util_parse_int(optarg, 1, EF_PROTO_PAYLOAD_MAX / EF_PROTO_CMD_BYTES, &v))
                return usage_error("--frame-cmds must be 1..5041, not '%s'", optarg);
            a->frame_cmds = (unsigned)v;
            break;
        case O_IFACES: a->interfaces = optarg; break;
        case O_JUNIT:
            if (!*optarg)
                return usage_error("--junit needs a file name, not '%s'", optarg);
            a->junit = optarg;
            break;
        case O_DIFF:
            a->diff_fmt = ef_util_format_from_path(optarg);
            if (a->diff_fmt != EF_UTIL_FMT_PNG && a->diff_fmt != EF_UTIL_FMT_PAM)
                return usage_error("--diff-image must name a .png (or .pam) file, not '%s'", optarg);
            if (!ef_util_format_available(a->diff_fmt))
                return usage_error("'%s': this edgeflag-host was built without PNG support (WITH_PNG=0); use .pam",
                                   optarg);
            a->diff_image = optarg;
            break;
        case O_ERRORS:
            if (!ef_util_parse_int(optarg, 0, INT32_MAX, &v))
                return usage_error("--errors must be a number 0..2147483647 (0 = all), not '%s'", optarg);
            a->errors = v;
            break;
        case O_TRANS: a->transactions = 1; break;
        case O_MIB:
            if (!ef_util_parse_int(optarg, 1, 65536, &v))
                return usage_error("--mib must be 1..65536, not '%s'", optarg);
            a->bench_bytes = (uint64_t)v << 20;
            break;
        case O_QUIET: a->quiet = 1; break;
        case O_JSON: a->json = 1; break;
        case O_HELP:
        case 'h': usage(stdout); exit(0);
        case ':': return usage_error("option %s needs a value", argv[optind - 1]);
        default: return usage_error("unknown option '%s'", argv[optind - 1]);
        }
    }
    if (a->junit && a->diff_image && strcmp(a->junit, a->diff_image) == 0)
        return usage_error("--junit and --diff-image name the same file ('%s')", a->junit);
    for (int i = optind; i < argc; i++) {
        if (a->vectors)
            return usage_error("one vectors file only ('%s' is one too many)", argv[i]);
        a->vectors = argv[i];
    }
    return 0;
}

/* Opens the named transport, or for auto the one board present. */
static int open_link(const args *a, const ef_transport_ops **ops, ef_link **l)
{
    char err[512] = "", auto_port[64] = "";
    ef_host_opts lo = a->link;
    const char *name = a->transport ? a->transport : "auto";
    if (strcmp(name, "auto") == 0) {
        ef_found found[16];
        int total = 0, nfound = 0, denied = 0;
        const ef_transport_ops *which = NULL;
        for (size_t i = 0; i < NPROBED; i++) { /* usb, gpio and serial: real boards only */
            if (PROBED[i] == &ef_transport_gpio && !a->link.chip)
                continue; /* a GPIO bus cannot be told from other GPIO use by looking */
            const int n = PROBED[i]->probe(&a->link, found + nfound, 16 - nfound);
            if (n < 0 && n != EF_HOST_EUNSUPPORTED && n != EF_HOST_ENOTFOUND) {
                fprintf(stderr, "edgeflag-host: looking for %s boards: %s\n", PROBED[i]->name, ef_host_strerror(n));
                return n == EF_HOST_EACCESS ? EF_HX_ACCESS : EF_HX_NOBOARD;
            }
            for (int k = 0; k < n && nfound < 16; k++, nfound++) {
                if (found[nfound].ok) {
                    which = PROBED[i], total++;
                    if (which == &ef_transport_serial) /* auto opens the port that answered */
                        snprintf(auto_port, sizeof auto_port, "%s", found[nfound].where);
                } else if (found[nfound].err == EF_HOST_EACCESS) {
                    denied++;
                }
            }
        }
        if (total != 1) {
            fprintf(stderr, "edgeflag-host: --transport auto: %s\n",
                    total ? "several boards answer; choose one with --transport and --device (edgeflag-host list)"
                          : "no board found (no USB device or FTDI serial port answers identify; GPIO needs "
                            "--chip and --lines); "
                            "use --transport sim for the simulated board");
            for (int k = 0; k < nfound; k++) /* what was seen, so the user can tell which */
                fprintf(stderr, "edgeflag-host:   %s %s %s%s\n", found[k].transport, found[k].where,
                        found[k].ok ? "" : "(not usable) ", found[k].desc);
            return !total && denied ? EF_HX_ACCESS : EF_HX_NOBOARD;
        }
        *ops = which;
        if (auto_port[0])
            lo.port = auto_port;
    } else {
        *ops = find_transport(name);
    }
    const int r = (*ops)->open(l, &lo, err, sizeof err);
    if (r < 0) {
        fprintf(stderr, "edgeflag-host: %s: %s%s%s\n", (*ops)->name, ef_host_strerror(r), err[0] ? ": " : "", err);
        return ef_host_exit_code(r);
    }
    return 0;
}

static int cmd_list(const args *a)
{
    ef_found found[32];
    int total = 0;
    if (a->json)
        fputs("{\"boards\": [", stdout);
    for (size_t i = 0; i < NPROBED; i++) {
        const int n = PROBED[i]->probe(&a->link, found, 32);
        if (n == EF_HOST_EUNSUPPORTED) {
            if (!a->json)
                printf("%s: %s\n", PROBED[i]->name, PROBED[i]->version());
            continue;
        }
        if (n < 0) {
            fprintf(stderr, "edgeflag-host: list: %s: %s\n", PROBED[i]->name, ef_host_strerror(n));
            continue;
        }
        for (int k = 0; k < n && k < 32; k++, total++) {
            if (a->json)
                printf("%s{\"transport\": \"%s\", \"where\": \"%s\", \"ours\": %s, \"description\": \"%s\"}",
                       total ? ", " : "", found[k].transport, found[k].where, found[k].ok ? "true" : "false",
                       found[k].desc);
            else
                printf("%-6s %-14s %s%s\n", found[k].transport, found[k].where, found[k].ok ? "" : "(not ours) ",
                       found[k].desc);
        }
    }
    if (a->json)
        printf("], \"count\": %d}\n", total);
    else if (total == 0)
        puts("no board found");
    return EF_HX_OK;
}

static uint32_t parse_ifaces(const char *list, int *bad)
{
    uint32_t m = 0;
    char buf[256];
    snprintf(buf, sizeof buf, "%s", list);
    for (char *save, *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        const int i = ef_iface_find(t);
        if (i < 0)
            *bad = 1;
        else
            m |= 1u << i;
    }
    return m;
}

static void mask_names(uint32_t m, char *buf, size_t size)
{
    size_t k = 0;
    buf[0] = 0;
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (m >> i & 1u)
            k += (size_t)snprintf(buf + k, size - k, "%s%s", k ? "," : "", ef_iface_get(i)->name);
}

static uint32_t file_mask(const char *path)
{
    uint8_t h[36];
    FILE *f = fopen(path, "rb");
    uint32_t m = 0;
    if (f && fread(h, 1, sizeof h, f) == sizeof h)
        m = (uint32_t)h[32] | (uint32_t)h[33] << 8 | (uint32_t)h[34] << 16 | (uint32_t)h[35] << 24;
    if (f)
        fclose(f);
    return m;
}

/* edgeflag-host's exit code for a check's status (docs/board.md section 7). */
static int check_exit(ef_check_status st)
{
    switch (st) {
    case EF_CHECK_PASS: return EF_HX_OK;
    case EF_CHECK_FAIL: return EF_HX_MISMATCH;
    case EF_CHECK_INPUT: return EF_HX_INPUT;
    case EF_CHECK_NOMEM: break;
    }
    return EF_HX_INTERNAL;
}

/* verify's check: the results the board sent (actual) against the vectors,
 * by the verifier library as `edgeflag check VECTORS.bin ACTUAL --interfaces
 * MASK` runs it: mismatch lines on stdout, status on stderr (none with
 * --quiet), then --junit and --diff-image written atomically.  An EF_HX_*. */
static int verify_results(const args *a, const char *actual, uint32_t mask)
{
    ef_check_opts o;
    ef_check_result res;
    ef_check_opts_defaults(&o);
    o.expected = a->vectors;
    o.actual = actual;
    o.only = mask;
    if (a->errors >= 0)
        o.errors = a->errors;
    o.cycles = !a->transactions;
    o.keep_marks = a->diff_image != NULL;
    o.report = stdout;
    o.status = a->quiet ? NULL : stderr;
    const ef_check_status st = ef_check_run(&o, &res);
    int out = EF_HX_OK;
    if (a->junit && st != EF_CHECK_NOMEM && ef_util_check_junit(&res, a->junit) != 0) {
        fprintf(stderr, "edgeflag-host: verify: cannot write '%s': %s\n", a->junit, strerror(errno));
        out = EF_HX_OUTPUT;
    }
    if (a->diff_image && (st == EF_CHECK_PASS || st == EF_CHECK_FAIL)) {
        char err[256];
        if (ef_util_check_diff_image(&res, a->diff_image, a->diff_fmt, err, sizeof err) != 0) {
            fprintf(stderr, "edgeflag-host: verify: cannot write '%s': %s\n", a->diff_image, err);
            out = errno == ENOMEM ? EF_HX_INTERNAL : EF_HX_OUTPUT;
        } else if (!a->quiet) {
            fprintf(stderr, "edgeflag-host: verify: wrote %s (%" PRIu64 " mismatching pixel runs marked)\n",
                    a->diff_image, res.marks);
        }
    }
    ef_check_result_destroy(&res);
    if (st != EF_CHECK_PASS && a->quiet)
        fprintf(stderr, "edgeflag-host: verify: FAIL (the check's status: %s)\n", ef_check_status_name(st));
    if (st != EF_CHECK_PASS && st != EF_CHECK_FAIL)
        return check_exit(st);
    return out != EF_HX_OK ? out : check_exit(st);
}

/* verify --save-frame: the board's pix results (RESULTS/vectors.actual.bin) as a PNG, atomically. */
static int save_frame(const char *actual, const char *path)
{
    ef_vec_dump d;
    ef_vec_read_error re;
    ef_image img;
    ef_util_atomic af;
    char err[900] = "";
    memset(&d, 0, sizeof d);
    int bad = ef_vec_read_path(actual, NULL, -1, -1, &d, &re) != EF_OK;
    if (bad)
        ef_vec_read_error_format(&re, err, sizeof err);
    else if (ef_check_frame_image(&d, &img, err, sizeof err) != 0)
        bad = 1;
    ef_vec_dump_destroy(&d);
    if (!bad) {
        if (ef_util_atomic_open(&af, path) != 0) {
            snprintf(err, sizeof err, "%s", strerror(errno));
            bad = 1;
        } else if (ef_util_write_image(af.fp, EF_UTIL_FMT_PNG, &img, err, sizeof err) != 0) {
            ef_util_atomic_abort(&af);
            bad = 1;
        } else if (ef_util_atomic_commit(&af) != 0) {
            snprintf(err, sizeof err, "%s", strerror(errno));
            bad = 1;
        }
        ef_image_destroy(&img);
    }
    if (bad)
        fprintf(stderr, "edgeflag-host: --save-frame %s: %s\n", path, err);
    return bad ? EF_HX_OUTPUT : EF_HX_OK;
}

static int cmd_stream(args *a, int verify)
{
    if (!a->vectors)
        return usage_error("%s needs a VECTORS.bin", a->cmd);
    char results[4096];
    if (a->results) {
        snprintf(results, sizeof results, "%s", a->results);
    } else {
        char tmp[4096];
        snprintf(tmp, sizeof tmp, "%s", a->vectors);
        snprintf(results, sizeof results, "%s/board", dirname(tmp));
    }
    uint32_t mask = 1u << EF_IF_PIX;
    if (a->interfaces) {
        int bad = 0;
        mask = parse_ifaces(a->interfaces, &bad);
        if (bad || !(mask >> EF_IF_PIX & 1u))
            return usage_error("--interfaces must be a comma-separated list of interfaces including pix, not '%s'",
                               a->interfaces);
    }
    if (!verify && (a->digest > 0 || a->save_frame))
        return usage_error("%s: --digest and --save-frame are verify's", a->cmd);
    const ef_transport_ops *ops;
    ef_link *l;
    int code = open_link(a, &ops, &l);
    if (code)
        return code;
    if (verify && !a->interfaces) { /* every interface both the file and the board have, but cmd */
        uint8_t raw[EF_PROTO_IDENTIFY_LEN];
        ef_host_ident id;
        if (ops->identify(l, raw) == 0 && ef_host_ident_parse(raw, &id) == 0)
            mask |= file_mask(a->vectors) & id.iface_mask & ~(1u << EF_IF_CMD);
    }
    const int auto_digest = a->digest < 0 && verify && ops == &ef_transport_serial; /* a slow line */
    ef_host_stream_opts so = { a->vectors,
                               results,
                               mask,
                               a->resume,
                               a->frame_cmds,
                               a->link.timeout_ms,
                               !a->quiet && isatty(2),
                               a->quiet,
                               auto_digest     ? 1024u
                               : a->digest > 0 ? (uint32_t)a->digest
                                               : 0u,
                               auto_digest,
                               a->digest_fetch };
    ef_host_stream_report rep;
    code = ef_host_stream(ops, l, &so, &rep);
    ops->close(l);
    char names[128];
    mask_names(mask, names, sizeof names);
    if (code == EF_HX_OK && !a->quiet && !a->json)
        fprintf(stderr,
                "edgeflag-host: %s: %" PRIu64 " commands in %" PRIu64 " frames (%" PRIu64 " sent again) to the %s "
                "board in %.3f s; %" PRIu64 " result records (%s) in %s/vectors.actual.bin\n",
                a->vectors, rep.cmds, rep.frames_sent - rep.retransmits, rep.retransmits, ops->name, rep.seconds,
                rep.records, names, results);
    int check = -1;
    if (code == EF_HX_OK && verify) {
        char actual[4200];
        snprintf(actual, sizeof actual, "%s/vectors.actual.bin", results);
        fflush(stdout);
        check = verify_results(a, actual, mask);
        code = check;
        if (a->save_frame && (code == EF_HX_OK || code == EF_HX_MISMATCH)) {
            const int s = save_frame(actual, a->save_frame);
            code = s ? s : code;
        }
    }
    if (a->json)
        printf("{\"command\": \"%s\", \"transport\": \"%s\", \"exit\": %d, \"vectors\": \"%s\", \"results\": \"%s\", "
               "\"interfaces\": \"%s\", \"commands\": %" PRIu64 ", \"frames_sent\": %" PRIu64
               ", \"retransmits\": %" PRIu64 ", \"naks\": %" PRIu64 ", \"timeouts\": %" PRIu64
               ", \"resumed_from_frame\": %" PRIu64 ", \"digest\": %" PRIu32 ", \"digest_windows\": %" PRIu64
               ", \"digest_differ\": %" PRIu64 ", \"digest_fetched\": %" PRIu64 ", \"result_records\": %" PRIu64
               ", \"result_bytes\": %" PRIu64 ", \"seconds\": %.6f, "
               "\"check\": %s}\n",
               a->cmd, ops->name, code, a->vectors, results, names, rep.cmds, rep.frames_sent, rep.retransmits,
               rep.naks, rep.timeouts, rep.resumed_from, rep.digest, rep.digest_windows, rep.digest_differ,
               rep.digest_fetched, rep.records, rep.result_bytes, rep.seconds,
               check < 0           ? "null"
               : check == EF_HX_OK ? "\"pass\""
                                   : "\"fail\"");
    return code;
}

static int cmd_bench(args *a)
{
    const ef_transport_ops *ops;
    ef_link *l;
    int code = open_link(a, &ops, &l);
    if (code)
        return code;
    ef_bench_result r[4];
    const int e = ef_bench_link(ops, l, a->bench_bytes ? a->bench_bytes : 64u << 20, a->link.timeout_ms, r);
    ops->close(l);
    if (e < 0) {
        fprintf(stderr, "edgeflag-host: bench over %s: %s\n", ops->name, ef_host_strerror(e));
        return ef_host_exit_code(e);
    }
    if (a->json)
        printf("{\"transport\": \"%s\"", ops->name);
    for (int i = 0; i < 4; i++) {
        if (a->json) {
            if (i < 3)
                printf(", \"%s\": {\"ran\": %s, \"bytes\": %" PRIu64 ", \"seconds\": %.6f, \"mb_s\": %.1f}", r[i].name,
                       r[i].ran ? "true" : "false", r[i].bytes, r[i].seconds, r[i].mb_s);
            else
                printf(", \"latency\": {\"usec_median\": %.1f, \"usec_min\": %.1f}}\n", r[i].usec_median,
                       r[i].usec_min);
        } else if (!r[i].ran) {
            printf("%-8s %-9s n/a (%s)\n", ops->name, r[i].name, r[i].note);
        } else if (i < 3) {
            printf("%-8s %-9s %10.1f MB/s  (%" PRIu64 " bytes in %.3f s)\n", ops->name, r[i].name, r[i].mb_s,
                   r[i].bytes, r[i].seconds);
        } else {
            printf("%-8s %-9s %10.1f us median, %.1f us min (%s)\n", ops->name, r[i].name, r[i].usec_median,
                   r[i].usec_min, r[i].note);
        }
    }
    return EF_HX_OK;
}

/* identify: the board's identify record (docs/board.md 3.1), decoded on standard output and,
 * with --save FILE, written to FILE as the 48 bytes it is, atomically: the file `edgeflag gen
 * --dut-file` reads (docs/gen.md section 11).  Nothing is written unless the record is an
 * edgeflag board's of this protocol version. */
static int cmd_identify(const args *a)
{
    const ef_transport_ops *ops;
    ef_link *l;
    int code = open_link(a, &ops, &l);
    if (code)
        return code;
    uint8_t raw[EF_PROTO_IDENTIFY_LEN];
    const int r = ops->identify(l, raw);
    if (r < 0) {
        const char *d = ops->detail ? ops->detail(l) : NULL;
        fprintf(stderr, "edgeflag-host: identify over %s: %s%s%s\n", ops->name, ef_host_strerror(r),
                d && *d ? ": " : "", d && *d ? d : "");
        ops->close(l);
        return ef_host_exit_code(r);
    }
    ops->close(l);
    ef_host_ident id;
    if (ef_host_ident_parse(raw, &id) != 0) {
        if (memcmp(raw, EF_PROTO_MAGIC, 4) == 0)
            fprintf(stderr,
                    "edgeflag-host: identify: the board speaks protocol version %u; this edgeflag-host speaks %d%s\n",
                    id.protocol, EF_PROTO_PROTOCOL, a->save ? " (nothing saved)" : "");
        else
            fprintf(stderr,
                    "edgeflag-host: identify: the device did not answer identify as an edgeflag board (no "
                    "\"EFB1\")%s\n",
                    a->save ? " (nothing saved)" : "");
        return EF_HX_BOARD;
    }
    if (a->save) {
        ef_util_atomic af;
        int bad = ef_util_atomic_open(&af, a->save) != 0;
        if (!bad && fwrite(raw, 1, sizeof raw, af.fp) != sizeof raw) {
            const int e = errno;
            ef_util_atomic_abort(&af);
            errno = e ? e : EIO;
            bad = 1;
        }
        if (!bad && ef_util_atomic_commit(&af) != 0)
            bad = 1;
        if (bad) {
            fprintf(stderr, "edgeflag-host: identify: cannot write '%s': %s\n", a->save, strerror(errno));
            return EF_HX_OUTPUT;
        }
    }
    char desc[300], ifaces[128], caps[128] = "";
    ef_host_ident_describe(&id, desc, sizeof desc);
    mask_names(id.iface_mask, ifaces, sizeof ifaces);
    static const char *const CAPS[4] = { "results", "resume", "internal interfaces", "digest" };
    for (int i = 0; i < 4; i++)
        if (id.caps >> i & 1u)
            snprintf(caps + strlen(caps), sizeof caps - strlen(caps), "%s%s", caps[0] ? ", " : "", CAPS[i]);
    if (a->json) {
        printf("{\"transport\": \"%s\", \"serial\": \"", ops->name);
        for (const char *p = id.serial; *p; p++) /* printable ASCII already (ef_host_ident_parse) */
            printf(*p == '"' || *p == '\\' ? "\\%c" : "%c", *p);
        printf("\", \"protocol\": %u, \"window\": %u, \"capabilities\": %" PRIu32 ", \"interfaces\": \"%s\", "
               "\"samples\": [",
               id.protocol, id.window, id.caps, ifaces);
        for (unsigned n = 8, k = 0; n <= 32; n *= 2)
            if (id.samples_mask >> ef_proto_samples_bit(n) & 1u)
                printf("%s%u", k++ ? ", " : "", n);
        printf("], \"width_max\": %" PRIu32 ", \"height_max\": %" PRIu32 ", \"edges_max\": %" PRIu32 ", \"saved\": ",
               id.width_max, id.height_max, id.edges_max);
        if (a->save) {
            putchar('"');
            for (const char *p = a->save; *p; p++)
                printf(*p == '"' || *p == '\\' ? "\\%c" : (unsigned char)*p < 0x20 ? "?" : "%c", *p);
            putchar('"');
        } else {
            fputs("null", stdout);
        }
        puts("}");
    } else {
        printf("%s: %s; capabilities: %s; interfaces: %s\n", ops->name, desc, caps[0] ? caps : "none",
               ifaces[0] ? ifaces : "none");
    }
    if (a->save && !a->quiet)
        fprintf(stderr,
                "edgeflag-host: identify: wrote %s (the 48-byte record of docs/board.md 3.1): edgeflag gen --dut-file "
                "%s fits cases to this board\n",
                a->save, a->save);
    return fflush(stdout) == 0 ? EF_HX_OK : EF_HX_OUTPUT;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return EF_HX_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return EF_HX_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("edgeflag-host %s (board protocol %d)\n", EF_VERSION_STRING, EF_PROTO_PROTOCOL);
        for (size_t i = 0; i < NTRANSPORTS; i++)
            printf("  %-5s %s\n", TRANSPORTS[i]->name, TRANSPORTS[i]->version());
        return EF_HX_OK;
    }
    args a;
    memset(&a, 0, sizeof a);
    a.digest = -1;
    a.cmd = argv[1];
    a.errors = -1;
    const int r = parse(argc - 1, argv + 1, &a);
    if (r)
        return r;
    if (a.save && strcmp(a.cmd, "identify") != 0)
        return usage_error("--save is identify's (verify saves a frame with --save-frame), not %s's", a.cmd);
    if (strcmp(a.cmd, "list") == 0)
        return a.vectors ? usage_error("list takes no file ('%s')", a.vectors) : cmd_list(&a);
    if (strcmp(a.cmd, "stream") == 0)
        return cmd_stream(&a, 0);
    if (strcmp(a.cmd, "verify") == 0)
        return cmd_stream(&a, 1);
    if (strcmp(a.cmd, "bench") == 0)
        return a.vectors ? usage_error("bench takes no file ('%s')", a.vectors) : cmd_bench(&a);
    if (strcmp(a.cmd, "identify") == 0)
        return a.vectors ? usage_error("identify takes no file ('%s'; --save FILE names the record's file)", a.vectors)
                         : cmd_identify(&a);
    return usage_error("unknown command '%s' (list, stream, verify, bench, identify)", a.cmd);
}
