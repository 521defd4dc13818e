// tb_files.vh - the file helpers the benches of dv/tb share (Verilog-2005,
// Icarus and Verilator alike), `included inside a bench's module body after
//     localparam TB_NAME = "tb_dec";   // the bench's name (unsized: Icarus 11
//                                       // prints a sized string parameter as "")
// (no include guard: every bench module that includes it gets its own tasks;
// the build needs -I dv/tb).  File names are regs of 8*240 bits.  A failure
// prints "TB_NAME: FAIL ..." and ends the run with $fatal: a non-zero exit
// (vvp exits 1, a Verilator binary aborts).
//
//   tb_fail(why)        "TB_NAME: FAIL why", then $fatal
//   tb_need(fname)      an input file that cannot be opened is a FAIL (never
//                       an empty memory that $readmemh only warns about)
//   tb_arg(got, what)   a required plusarg: got = $value$plusargs(...); 0 is
//                       a FAIL "no +what" (a bench reads and writes only the
//                       files it is told)
//   tb_open_out(f, fname, iface, desc)  opens a dump for writing (a FAIL if
//                       it cannot) and writes the header line of an actual
//                       dump: "// edgeflag vectors format 1: interface IFACE
//                       (DESC), role actual: dv/tb/TB_NAME.v"

    task tb_fail;
        input [8*300-1:0] why;
        begin
            $display("%0s: FAIL %0s", TB_NAME, why);
            $fatal(1, "%0s: FAIL", TB_NAME);
        end
    endtask

    task tb_need;
        input [8*240-1:0] fname;
        integer fdn;
        reg [8*300-1:0] msg;
        begin
            fdn = $fopen(fname, "r");
            if (fdn == 0) begin
                $sformat(msg, "cannot open %0s", fname);
                tb_fail(msg);
            end
            $fclose(fdn);
        end
    endtask

    task tb_arg;
        input integer got;
        input [8*80-1:0] what;
        reg [8*300-1:0] msg;
        begin
            if (got == 0) begin
                $sformat(msg, "no +%0s", what);
                tb_fail(msg);
            end
        end
    endtask

    task tb_open_out;
        output integer f;
        input [8*240-1:0] fname;
        input [8*16-1:0] iface;
        input [8*40-1:0] desc;
        reg [8*300-1:0] msg;
        begin
            f = $fopen(fname, "w");
            if (f == 0) begin
                $sformat(msg, "cannot open %0s for writing", fname);
                tb_fail(msg);
            end
            $fwrite(f, "// edgeflag vectors format 1: interface %0s (%0s), role actual: dv/tb/%0s.v\n", iface, desc,
                    TB_NAME);
        end
    endtask
