// tb_etm: block-level testbench of rtl/ef_etm.v (ETM).
//
// Replays et_wr.expected.hex (the block's stimulus) at its stamped cycles
// and plays the AET/sequencer's part in the row requests: for every pixel
// row the reference schedule rasterizes it raises row_req in the cycle
// before the row's first cycle, which is the cycle of the row's first
// et_rd (et_rd.expected.hex) or, for a row whose slot is empty (an AET that
// is not), L_PLOT cycles before its first plot (plot.expected.hex: a row's
// plots end with last = 1).  et_rd_ready is always high (the reference AET).  Every et_rd
// transfer is recorded with its cycle as et_rd.actual.hex for
// `edgeflag check et_rd.expected.hex et_rd.actual.hex --cycles`, so a list
// in the wrong order, a slot not cleared when taken (an edge again in a
// later shape), an empty slot that yields an edge or a late first edge all
// fail there.  The bench also checks, itself: the record read port (the
// record of each et_rd's eid, read in its transfer cycle, equals that
// edge's et_wr), every requested row inside row_first..row_last and the
// first one of a shape (requested in its eos cycle) equal to row_first.
// Cycle 0 is the first cycle after the reset sweep (init_done).  Bit
// positions come from the generated ef_ifaces.vh (docs/vectors.md 8).
//
// Parameters: NS, H_MAX, E_MAX, NWR, NRD, NPLOT (NCMD unused);
// plusargs +et_wr_in= +et_rd_exp= +plot= +et_rd= (paths, required).
// Result line: "tb_etm: DONE ..." (exit 0) or "tb_etm: FAIL ..." (exit
// non-zero: a bench check, a refused stream, a file that cannot be opened, a
// missing plusarg; the file helpers are dv/tb/tb_files.vh).
`include "ef_ifaces.vh"
module tb_etm #(
    parameter NS    = 8,
    parameter H_MAX = 16384,
    parameter E_MAX = 16384,
    parameter NWR   = 1,
    parameter NRD   = 1,
    parameter NPLOT = 1,
    /* verilator lint_off UNUSEDPARAM */
    parameter NCMD  = 1                 // unused: the scripts pass it to every block bench
    /* verilator lint_on UNUSEDPARAM */
);
    localparam WWD = `EF_ET_WR_WORD_W;
    localparam RWD = `EF_ET_RD_WORD_W;
    localparam PWD = `EF_PLOT_WORD_W;
    localparam NREQ = NRD + NPLOT + 1;

    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg rst = 1'b1;

    reg        wr_valid = 1'b0, wr_eos = 1'b0, wr_dir = 1'b0;
    reg [13:0] wr_slot = 14'd0;
    reg [18:0] wr_r0 = 19'd0, wr_r1 = 19'd0;
    reg [24:0] wr_x = 25'd0;
    reg [23:0] wr_e = 24'd0, wr_rs = 24'd0, wr_dy = 24'd0;
    reg [29:0] wr_qs = 30'd0;
    reg        row_req = 1'b0;
    reg [13:0] row_req_row = 14'd0;
    wire       init_done, wr_ready, shape_go, shape_any, err_full, row_req_ready;
    /* verilator lint_off UNUSEDSIGNAL */
    wire       rd_last;   // the dump and check show what it would
    /* verilator lint_on UNUSEDSIGNAL */
    wire [13:0] row_first, row_last, rd_row;
    wire       rd_valid;
    wire [21:0] rd_eid;
    wire [18:0] rec_r0, rec_r1;
    wire [24:0] rec_x;
    wire [23:0] rec_e, rec_rs, rec_dy;
    wire [29:0] rec_qs;
    wire        rec_dir;

    ef_etm #(.NS(NS), .H_MAX(H_MAX), .E_MAX(E_MAX)) dut (
        .clk(clk), .rst(rst), .init_done(init_done),
        .et_wr_valid(wr_valid), .et_wr_ready(wr_ready), .et_wr_eos(wr_eos), .et_wr_slot(wr_slot),
        .et_wr_r0(wr_r0), .et_wr_r1(wr_r1), .et_wr_x(wr_x), .et_wr_e(wr_e), .et_wr_qs(wr_qs),
        .et_wr_rs(wr_rs), .et_wr_dy(wr_dy), .et_wr_dir(wr_dir),
        .shape_go(shape_go), .shape_any(shape_any), .row_first(row_first), .row_last(row_last),
        .err_full(err_full),
        .row_req(row_req), .row_req_ready(row_req_ready), .row_req_row(row_req_row),
        .et_rd_valid(rd_valid), .et_rd_ready(1'b1), .et_rd_row(rd_row), .et_rd_eid(rd_eid),
        .et_rd_last(rd_last),
        .rec_re(rd_valid), .rec_ra(rd_eid), .rec_r0(rec_r0), .rec_r1(rec_r1), .rec_x(rec_x), .rec_e(rec_e),
        .rec_qs(rec_qs), .rec_rs(rec_rs), .rec_dy(rec_dy), .rec_dir(rec_dir)
    );

    reg [WWD-1:0] wr_mem  [0:NWR];
    reg [RWD-1:0] rd_mem  [0:NRD];
    reg [PWD-1:0] pl_mem  [0:NPLOT];
    reg [13:0]    rq_row  [0:NREQ];
    reg [47:0]    rq_cyc  [0:NREQ];    // the row's first cycle
    reg [8*240-1:0] wr_name, rd_name, pl_name, out_name;
    integer iw, k, nreq, irq, nrd, errors, fo, nshape, wr_base, rd_base, rec_chk;
    reg [47:0] cyc, last;
    reg        running, done, chk_pending, first_after_go;
    reg [21:0] chk_eid;
    reg [RWD-1:0] word;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [WWD-1:0] w;                    // an et_wr word: its payload is compared, not its stamp
    /* verilator lint_on UNUSEDSIGNAL */

    // rows: et_rd group starts, then rows whose first plot is not preceded
    // by their own et_rd, merged in cycle order (both lists are sorted).
    task build_requests;
        integer a, p;
        begin
            nreq = 0;
            a = 0;                           // et_rd index
            for (p = 0; p < NPLOT; p = p + 1) begin
                if (p == 0 || pl_mem[p-1][`EF_PLOT_LAST_LSB]) begin
                    // et_rd groups starting before this plot row come first
                    while (a < NRD && rd_mem[a][RWD-1 -: 48] < pl_mem[p][PWD-1 -: 48]) begin
                        if (a == 0 || rd_mem[a][`EF_ET_RD_ROW_MSB:`EF_ET_RD_ROW_LSB] !=
                                      rd_mem[a-1][`EF_ET_RD_ROW_MSB:`EF_ET_RD_ROW_LSB] ||
                            rd_mem[a][RWD-1 -: 48] != rd_mem[a-1][RWD-1 -: 48] + 1) begin
                            rq_row[nreq] = rd_mem[a][`EF_ET_RD_ROW_MSB:`EF_ET_RD_ROW_LSB];
                            rq_cyc[nreq] = rd_mem[a][RWD-1 -: 48];
                            nreq = nreq + 1;
                        end
                        a = a + 1;
                    end
                    // a row with et_rd has its first plot L_REC + L_PLOT cycles after
                    // the cycle that follows its last et_rd (docs/microarch.md section 4,
                    // item 4); one without starts L_PLOT cycles before its first plot
                    if (!(a > 0 && rd_mem[a-1][RWD-1 -: 48] + 1 + `EF_L_REC + `EF_L_PLOT == pl_mem[p][PWD-1 -: 48] &&
                          rd_mem[a-1][`EF_ET_RD_ROW_MSB:`EF_ET_RD_ROW_LSB] ==
                          pl_mem[p][`EF_PLOT_ROW_MSB:`EF_PLOT_ROW_LSB])) begin
                        rq_row[nreq] = pl_mem[p][`EF_PLOT_ROW_MSB:`EF_PLOT_ROW_LSB];
                        rq_cyc[nreq] = pl_mem[p][PWD-1 -: 48] - `EF_L_PLOT;
                        nreq = nreq + 1;
                    end
                end
            end
            if (a < NRD) begin
                $display("tb_etm: %0d et_rd after the last plot row", NRD - a);
                errors = errors + 1;
            end
        end
    endtask

    task present;
        input [47:0] c;
        begin
            wr_valid <= 1'b0;
            if (iw < NWR && wr_mem[iw][WWD-1 -: 48] == c) begin
                w = wr_mem[iw];
                wr_valid <= 1'b1;
                wr_eos  <= w[`EF_ET_WR_EOS_LSB];
                wr_slot <= w[`EF_ET_WR_SLOT_MSB:`EF_ET_WR_SLOT_LSB];
                wr_r0   <= w[`EF_ET_WR_R0_MSB:`EF_ET_WR_R0_LSB];
                wr_r1   <= w[`EF_ET_WR_R1_MSB:`EF_ET_WR_R1_LSB];
                wr_x    <= w[`EF_ET_WR_X_MSB:`EF_ET_WR_X_LSB];
                wr_e    <= w[`EF_ET_WR_E_MSB:`EF_ET_WR_E_LSB];
                wr_qs   <= w[`EF_ET_WR_QS_MSB:`EF_ET_WR_QS_LSB];
                wr_rs   <= w[`EF_ET_WR_RS_MSB:`EF_ET_WR_RS_LSB];
                wr_dy   <= w[`EF_ET_WR_DY_MSB:`EF_ET_WR_DY_LSB];
                wr_dir  <= w[`EF_ET_WR_DIR_LSB];
                if (w[`EF_ET_WR_EOS_LSB]) begin
                    rd_base = wr_base;
                    wr_base = iw + 1;
                end
                iw = iw + 1;
            end
            // request the row whose first cycle is c + 1
            row_req <= 1'b0;
            if (irq < nreq && rq_cyc[irq] == c + 1) begin
                row_req <= 1'b1;
                row_req_row <= rq_row[irq];
                irq = irq + 1;
            end
        end
    endtask

    localparam TB_NAME = "tb_etm";
`include "tb_files.vh"

    initial begin
        tb_arg($value$plusargs("et_wr_in=%s", wr_name), "et_wr_in=FILE (et_wr.expected.hex)");
        tb_arg($value$plusargs("et_rd_exp=%s", rd_name), "et_rd_exp=FILE (et_rd.expected.hex)");
        tb_arg($value$plusargs("plot=%s", pl_name), "plot=FILE (plot.expected.hex)");
        tb_arg($value$plusargs("et_rd=%s", out_name), "et_rd=FILE (where the et_rd dump goes)");
        tb_need(wr_name); tb_need(rd_name); tb_need(pl_name);
        if (NWR > 0)   $readmemh(wr_name, wr_mem, 0, NWR - 1);
        if (NRD > 0)   $readmemh(rd_name, rd_mem, 0, NRD - 1);
        if (NPLOT > 0) $readmemh(pl_name, pl_mem, 0, NPLOT - 1);
        errors = 0;
        for (k = 1; k < NWR; k = k + 1)
            if (wr_mem[k][WWD-1 -: 48] <= wr_mem[k-1][WWD-1 -: 48]) begin
                $display("tb_etm: FAIL %0s: word %0d (line %0d): cycle stamp %0d does not increase",
                         wr_name, k, k + 5, wr_mem[k][WWD-1 -: 48]);
                $fatal(1, "tb_etm: FAIL");
            end
        k = 0;
        for (iw = 0; iw < NWR; iw = iw + 1) begin
            if (wr_mem[iw][`EF_ET_WR_EOS_LSB])
                k = 0;
            else begin
                k = k + 1;
                if (k > E_MAX) begin
                    $display("tb_etm: FAIL %0s: word %0d (line %0d): a shape of more than E_MAX=%0d edges",
                             wr_name, iw, iw + 5, E_MAX);
                    $fatal(1, "tb_etm: FAIL");
                end
                if ({18'd0, wr_mem[iw][`EF_ET_WR_SLOT_MSB:`EF_ET_WR_SLOT_LSB]} >= H_MAX) begin
                    $display("tb_etm: FAIL %0s: word %0d (line %0d): slot %0d outside H_MAX=%0d",
                             wr_name, iw, iw + 5, wr_mem[iw][`EF_ET_WR_SLOT_MSB:`EF_ET_WR_SLOT_LSB], H_MAX);
                    $fatal(1, "tb_etm: FAIL");
                end
            end
        end
        build_requests;
        iw = 0; irq = 0; nrd = 0; nshape = 0; wr_base = 0; rd_base = 0; rec_chk = 0;
        running = 1'b0; done = 1'b0; chk_pending = 1'b0; first_after_go = 1'b0; cyc = 0;
        last = NWR > 0 ? wr_mem[NWR-1][WWD-1 -: 48] : 48'd0;
        if (nreq > 0 && rq_cyc[nreq-1] > last) last = rq_cyc[nreq-1];
        if (NRD > 0 && rd_mem[NRD-1][RWD-1 -: 48] > last) last = rd_mem[NRD-1][RWD-1 -: 48];
        tb_open_out(fo, out_name, "et_rd", "ETM -> AET");
        repeat (3) @(posedge clk);
        @(negedge clk);       // no rising edge sees reset change
        rst = 1'b0;
    end

    always @(posedge clk) begin
        if (!running) begin
            if (!rst && init_done) begin
                running <= 1'b1;
                cyc <= 48'd0;
                present(48'd0);
            end
        end else if (!done) begin
            if (wr_valid && !wr_ready) begin
                if (errors < 10) $display("tb_etm: cycle %0d: ETM not ready for the stamped et_wr", cyc);
                errors = errors + 1;
            end
            if (row_req && !row_req_ready) begin
                if (errors < 10) $display("tb_etm: cycle %0d: ETM not ready for the row request", cyc);
                errors = errors + 1;
            end
            // the record read in the previous et_rd's transfer cycle
            if (chk_pending) begin
                w = wr_mem[rd_base + {10'd0, chk_eid}];
                if (rec_r0 !== w[`EF_ET_WR_R0_MSB:`EF_ET_WR_R0_LSB] || rec_r1 !== w[`EF_ET_WR_R1_MSB:`EF_ET_WR_R1_LSB] ||
                    rec_x !== w[`EF_ET_WR_X_MSB:`EF_ET_WR_X_LSB] || rec_e !== w[`EF_ET_WR_E_MSB:`EF_ET_WR_E_LSB] ||
                    rec_qs !== w[`EF_ET_WR_QS_MSB:`EF_ET_WR_QS_LSB] || rec_rs !== w[`EF_ET_WR_RS_MSB:`EF_ET_WR_RS_LSB] ||
                    rec_dy !== w[`EF_ET_WR_DY_MSB:`EF_ET_WR_DY_LSB] || rec_dir !== w[`EF_ET_WR_DIR_LSB]) begin
                    if (errors < 10) $display("tb_etm: cycle %0d: record %0d read back differs from its et_wr", cyc, chk_eid);
                    errors = errors + 1;
                end
                rec_chk = rec_chk + 1;
            end
            chk_pending = rd_valid;
            chk_eid = rd_eid;
            if (shape_go)
                nshape = nshape + 1;
            if (wr_valid && wr_eos)      // the first row is requested in the eos cycle
                first_after_go = shape_any;
            if (row_req) begin
                if (first_after_go && row_req_row != row_first) begin
                    if (errors < 10) $display("tb_etm: cycle %0d: first row %0d, row_first %0d", cyc, row_req_row, row_first);
                    errors = errors + 1;
                end
                if (row_req_row < row_first || row_req_row > row_last) begin
                    if (errors < 10) $display("tb_etm: cycle %0d: row %0d outside row_first..row_last = %0d..%0d",
                                              cyc, row_req_row, row_first, row_last);
                    errors = errors + 1;
                end
                first_after_go = 1'b0;
            end
            if (rd_valid) begin
                word = {RWD{1'b0}};
                word[RWD-1 -: 48] = cyc;
                word[`EF_ET_RD_ROW_MSB:`EF_ET_RD_ROW_LSB] = rd_row;
                word[`EF_ET_RD_EID_MSB:`EF_ET_RD_EID_LSB] = rd_eid;
                $fwrite(fo, "%h\n", word);
                nrd = nrd + 1;
            end
            if (err_full) begin
                $display("tb_etm: cycle %0d: err_full", cyc);
                errors = errors + 1;
            end
            if (cyc > last + 4) begin
                done <= 1'b1;
                $fclose(fo);
                if (errors == 0)
                    $display("tb_etm: DONE NS=%0d: %0d et_wr, %0d row requests, %0d et_rd, %0d records read back, %0d shapes",
                             NS, NWR, nreq, nrd, rec_chk, nshape);
                else
                    $display("tb_etm: FAIL NS=%0d: %0d errors", NS, errors);
                if (errors != 0) $fatal(1, "tb_etm: FAIL");
                $finish;
            end
            cyc <= cyc + 48'd1;
            present(cyc + 48'd1);
        end
    end
endmodule
