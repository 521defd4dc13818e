/*
 * dut_rtl.cpp - the C++ that Verilator needs and nothing more: each sample
 * count's Verilated ef_rtl_dut (dv/tb/dut_rtl.v around ef_raster,
 * built by board/rtl_dut.mk with --prefix Vef_rtl_dutNS) behind the plain C
 * calls of dut_rtl.h.  The DUT's logic is in dut_rtl.c.
 *
 * EF_RTL_NS8, EF_RTL_NS16, EF_RTL_NS32: which models were built.
 */
#include <new>

#include "verilated.h"

#include "dut_rtl.h"
#ifdef EF_RTL_NS8
#include "Vef_rtl_dut8.h"
#endif
#ifdef EF_RTL_NS16
#include "Vef_rtl_dut16.h"
#endif
#ifdef EF_RTL_NS32
#include "Vef_rtl_dut32.h"
#endif

/* Verilator's runtime wants this for $time; the models use no delays. */
double sc_time_stamp() { return 0; }

struct ef_rtl_sim {
    virtual ~ef_rtl_sim() {}
    virtual void eval(const ef_rtl_in *in, ef_rtl_out *out) = 0;
    virtual void tick() = 0;
};

namespace
{

template <class V> struct model : ef_rtl_sim {
    VerilatedContext ctx;
    V *v;
    model() : v(new V(&ctx))
    {
        v->clk = 0;
        v->rst = 1;
        v->eval();
    }
    ~model() override
    {
        v->final();
        delete v;
    }
    void eval(const ef_rtl_in *in, ef_rtl_out *o) override
    {
        v->rst = in->rst;
        v->cmd_valid = in->cmd_valid;
        v->cmd_op = in->cmd_op;
        v->cmd_a = in->cmd_a;
        v->cmd_b = in->cmd_b;
        v->cmd_c = in->cmd_c;
        v->cmd_d = in->cmd_d;
        v->pix_ready = in->pix_ready;
        v->fb_rdata = in->fb_rdata;
        v->eval();
        o->init_done = v->init_done, o->drained = v->drained, o->cmd_ready = v->cmd_ready;
        o->err = v->err, o->frame_start = v->frame_start, o->frame_end = v->frame_end;
        o->pix_valid = v->pix_valid, o->pix_y = v->pix_y, o->pix_x = v->pix_x;
        o->pix_alpha = v->pix_alpha, o->pix_rgba = v->pix_rgba;
        o->fb_re = v->fb_re, o->fb_ry = v->fb_ry, o->fb_rx = v->fb_rx;
        o->fb_we = v->fb_we, o->fb_wy = v->fb_wy, o->fb_wx = v->fb_wx, o->fb_wdata = v->fb_wdata;
        o->seg_valid = v->seg_valid, o->seg_ready = v->seg_ready, o->seg_eos = v->seg_eos;
        o->seg_xa = v->seg_xa, o->seg_ya = v->seg_ya, o->seg_xb = v->seg_xb, o->seg_yb = v->seg_yb;
        o->et_wr_valid = v->et_wr_valid, o->et_wr_ready = v->et_wr_ready, o->et_wr_eos = v->et_wr_eos;
        o->et_wr_dir = v->et_wr_dir, o->et_wr_slot = v->et_wr_slot, o->et_wr_r0 = v->et_wr_r0;
        o->et_wr_r1 = v->et_wr_r1, o->et_wr_x = v->et_wr_x, o->et_wr_e = v->et_wr_e;
        o->et_wr_qs = v->et_wr_qs, o->et_wr_rs = v->et_wr_rs, o->et_wr_dy = v->et_wr_dy;
        o->et_rd_valid = v->et_rd_valid, o->et_rd_ready = v->et_rd_ready;
        o->et_rd_row = v->et_rd_row, o->et_rd_eid = v->et_rd_eid;
        o->plot_valid = v->plot_valid, o->plot_ready = v->plot_ready, o->plot_last = v->plot_last;
        o->plot_dir = v->plot_dir, o->plot_row = v->plot_row, o->plot_s = v->plot_s, o->plot_q = v->plot_q;
        o->span_valid = v->span_valid, o->span_ready = v->span_ready, o->span_y = v->span_y;
        o->span_x = v->span_x, o->span_len = v->span_len, o->span_mask = v->span_mask;
    }
    /* The falling edge is left to the next eval(): nothing in the RTL runs
     * on it, and the next inputs are applied then anyway (one eval less
     * per cycle). */
    void tick() override
    {
        v->clk = 1;
        v->eval();
        v->clk = 0;
    }
};

template <class V> ef_rtl_sim *make() { return new (std::nothrow) model<V>(); }

}   // namespace

extern "C" ef_rtl_sim *ef_rtl_sim_new(int ns)
{
    try {
        switch (ns) {
#ifdef EF_RTL_NS8
        case 8: return make<Vef_rtl_dut8>();
#endif
#ifdef EF_RTL_NS16
        case 16: return make<Vef_rtl_dut16>();
#endif
#ifdef EF_RTL_NS32
        case 32: return make<Vef_rtl_dut32>();
#endif
        default: return nullptr;
        }
    } catch (...) {
        return nullptr; /* std::bad_alloc from inside the model */
    }
}

extern "C" void ef_rtl_sim_free(ef_rtl_sim *s) { delete s; }

extern "C" void ef_rtl_sim_eval(ef_rtl_sim *s, const ef_rtl_in *in, ef_rtl_out *out) { s->eval(in, out); }

extern "C" void ef_rtl_sim_tick(ef_rtl_sim *s) { s->tick(); }

extern "C" uint32_t ef_rtl_sim_samples_mask(void)
{
    uint32_t m = 0;
#ifdef EF_RTL_NS8
    m |= 1u << 3;
#endif
#ifdef EF_RTL_NS16
    m |= 1u << 4;
#endif
#ifdef EF_RTL_NS32
    m |= 1u << 5;
#endif
    return m;
}
