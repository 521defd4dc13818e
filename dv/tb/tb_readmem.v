// tb_readmem: does a real simulator read an `edgeflag vectors` hex file the
// way `edgeflag check` does?  (docs/vectors.md section 3)
//
// Loads IN_FILE with $readmemh into a memory of DEPTH+1 words of 48+P bits,
// and checks, independently of our C readers:
//   * the header comments (read with $fgets/$sscanf, which $readmemh skips):
//     the interface name, "word N bits" = 48+P, and "count N" = DEPTH;
//   * that $readmemh loaded exactly DEPTH words (a sentinel in every word
//     before the load; the extra word DEPTH must keep it, else the file has
//     more words than the header says);
//   * that cycle stamps (word[48+P-1 -: 48]) never decrease and, because a
//     valid/ready stream transfers at most once per cycle (microarch 2),
//     strictly increase;
// then writes every word back with $fwrite("%h\n") to OUT_FILE, the layout
// an RTL dump has, so the caller can run `edgeflag check IN OUT` on the pair.
//
// Parameters (iverilog -P tb_readmem.X=..., verilator -GX=...):
//   P        payload bits of the interface (cmd 100, edge 97, et_wr 181,
//            et_rd 36, plot 36, span 75, pix 68)
//   DEPTH    transaction count (from manifest.json / the header)
//   IFACE    interface name as in the header ("span"); "" skips the check
//   IN_FILE, OUT_FILE  paths; plusargs +in=PATH +out=PATH override them
//   FINISH   1: call $finish (top level); 0: when instantiated by a wrapper
// Result: one line "tb_readmem <iface>: PASS ..." (exit 0) or "... FAIL ..."
// (with FINISH 1, exit non-zero by $fatal: vvp exits 1, a Verilator binary
// aborts; tb_readmem_all does the same for its seven instances).
module tb_readmem #(
    parameter P        = 75,
    parameter DEPTH    = 1,
    parameter IFACE    = "",
    parameter IN_FILE  = "in.hex",
    parameter OUT_FILE = "out.hex",
    parameter FINISH   = 1
);
    localparam WB = 48 + P;

    reg [WB-1:0] mem [0:DEPTH];          // one guard word past the count
    reg [WB-1:0] sentinel;
    reg [47:0]   cyc, prev;
    reg [8*240-1:0] in_name, out_name;   // < 2048 bits: the string limit of verilated code
    reg [8*240-1:0] line;
    reg [8*64-1:0]   word_s;
    integer fd, fo, i, n, r, loaded, errors, hdr_count, hdr_bits, fmt;
    reg     have_iface, in_header, in_ok;

    task fail;
        input [8*160-1:0] msg;
        begin
            errors = errors + 1;
            if (errors <= 10)
                $display("tb_readmem %0s: error: %0s", IFACE, msg);
        end
    endtask

    initial begin
        errors = 0; hdr_count = -1; hdr_bits = -1; have_iface = 0;
        // (string parameters into the name registers: zero-extended, as meant)
        /* verilator lint_off WIDTH */
        in_name = IN_FILE; out_name = OUT_FILE;
        if (!$value$plusargs("in=%s", in_name))  in_name  = IN_FILE;
        if (!$value$plusargs("out=%s", out_name)) out_name = OUT_FILE;
        /* verilator lint_on WIDTH */

        // 1. Header comments: $readmemh ignores them, so read them as text.
        fd = $fopen(in_name, "r");
        in_ok = fd != 0;
        if (fd == 0) begin
            fail("cannot open the input file");
        end else begin
            // The header is the leading comment lines: stop at the first
            // other line (reading all of a big file through $fgets is slow).
            in_header = 1;
            while (in_header && !$feof(fd)) begin
                line = 0;
                r = $fgets(line, fd);
                if (r > 0 && r <= 240) begin
                    // $fgets leaves the text right-aligned behind NUL bytes,
                    // which verilated $sscanf does not skip: left-align it.
                    line = line << (8 * (240 - r));
                    if (line[8*240-1 -: 16] != "//")
                        in_header = 0;
                    else if ($sscanf(line, "// count %d", n) == 1)
                        hdr_count = n;
                    else if ($sscanf(line, "// word %d bits", n) == 1)
                        hdr_bits = n;
                    else if ($sscanf(line, "// edgeflag vectors format %d: interface %s",
                                     fmt, word_s) == 2) begin
                        have_iface = 1;
                        /* verilator lint_off WIDTH */
                        if (IFACE != "" && word_s != IFACE)
                        /* verilator lint_on WIDTH */
                            fail("header names another interface");
                        if (fmt != 1)
                            fail("header format is not 1");
                    end
                end
            end
            $fclose(fd);
        end
        if (hdr_count != DEPTH) begin
            $display("tb_readmem %0s: header count %0d, DEPTH %0d", IFACE, hdr_count, DEPTH);
            fail("header count differs from DEPTH (manifest)");
        end
        if (hdr_bits != WB) begin
            $display("tb_readmem %0s: header word bits %0d, 48+P = %0d", IFACE, hdr_bits, WB);
            fail("header word width differs from 48+P");
        end
        if (!have_iface)
            fail("no '// edgeflag vectors format' header line");

        // 2. The words.  All-ones cannot be a transaction (cycle 2^48-1).
        sentinel = {WB{1'b1}};
        for (i = 0; i <= DEPTH; i = i + 1)
            mem[i] = sentinel;
        $readmemh(in_name, mem);
        loaded = DEPTH + 1;
        for (i = DEPTH; i >= 0; i = i - 1)
            if (mem[i] === sentinel)
                loaded = i;
        for (i = 0; i < DEPTH; i = i + 1)
            if (mem[i] === sentinel || ^mem[i] === 1'bx)
                fail("a word before DEPTH is missing or unknown");
        if (mem[DEPTH] !== sentinel)
            fail("the file holds more words than DEPTH");
        if (loaded != DEPTH)
            $display("tb_readmem %0s: loaded %0d words, DEPTH %0d", IFACE, loaded, DEPTH);

        // 3. Cycle stamps.
        prev = 0;
        for (i = 0; i < DEPTH; i = i + 1) begin
            cyc = mem[i][WB-1 -: 48];
            if (i > 0 && cyc < prev) begin
                if (errors < 10) $display("tb_readmem %0s: word %0d cycle %0d after %0d", IFACE, i, cyc, prev);
                fail("cycle stamps decrease");
            end else if (i > 0 && cyc == prev) begin
                if (errors < 10) $display("tb_readmem %0s: word %0d cycle %0d repeated", IFACE, i, cyc);
                fail("two transfers in one cycle on one stream");
            end
            prev = cyc;
        end

        // 4. Write back in the RTL dump layout (not when there was no input).
        fo = 1;
        if (in_ok)
            fo = $fopen(out_name, "w");
        if (!in_ok)
            ;
        else if (fo == 0)
            fail("cannot open the output file");
        else begin
            // No header: the bare layout of an RTL dump ($fwrite("%h\n")),
            // except that an empty dump needs one comment line (edgeflag
            // check refuses an empty file).
            if (DEPTH == 0)
                $fwrite(fo, "// tb_readmem: no %0s transactions\n", IFACE);
            for (i = 0; i < DEPTH; i = i + 1)
                $fwrite(fo, "%h\n", mem[i]);
            $fclose(fo);
        end

        if (errors == 0)
            $display("tb_readmem %0s: PASS %0d words of %0d bits, cycles %0d..%0d",
                     IFACE, DEPTH, WB, DEPTH > 0 ? mem[0][WB-1 -: 48] : 0, prev);
        else
            $display("tb_readmem %0s: FAIL %0d errors", IFACE, errors);
        if (FINISH) begin
            if (errors != 0) $fatal(1, "tb_readmem: FAIL");
            $finish;
        end
    end
endmodule
