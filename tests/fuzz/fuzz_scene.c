/*
 * fuzz_scene.c - libFuzzer target for the peerbench `.scene` text reader
 * (model/input/scene_text.c).
 *
 * For each input: load it as is and fitted into a small canvas; both runs
 * must satisfy the reader contract (fuzz_common.h), load twice to the same
 * result, and a successful load written back as exact text must read back
 * to the same vertices.
 */
#include "fuzz_common.h"

static const char NAME[] = "fuzz.scene";

static void one(const char *data, size_t size, const ef_load_opts *opts)
{
    ef_scene s, t;
    ef_error e;
    if (!fuzz_load_checked(ef_scene_load_text, NAME, data, size, opts, &s))
        return;

    fuzz_buf b = { 0 };
    fuzz_scene_text(&s, &b);
    ef_status ts = ef_scene_load_text("dump.scene", b.p, b.n, NULL, &t, &e);
    FUZZ_CHECK(ts == EF_OK, "the exact dump does not load: %s", e.msg);
    FUZZ_CHECK(fuzz_same_geometry(&s, &t), "the exact dump reads back different vertices");
    ef_scene_destroy(&t);
    free(b.p);
    ef_scene_destroy(&s);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ef_load_opts fit;
    memset(&fit, 0, sizeof fit);
    fit.fit_width = 41;
    fit.fit_height = 17;
    one((const char *)data, size, NULL);
    one((const char *)data, size, &fit);
    return 0;
}
