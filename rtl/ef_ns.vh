// ef_ns.vh - the sample count's one definition in the RTL: included inside
// the body of every module with the parameter NS (samples per pixel), it
// gives LOG2NS = log2(NS) and fails elaboration for an NS other than 8, 16
// or 32 (docs/spec.md section 4): the generate branch then instantiates a
// module that does not exist, which every Verilog-2005 tool (Verilator,
// Icarus, Yosys) reports as an error naming it.
/* verilator lint_off UNUSEDPARAM */
localparam integer LOG2NS = (NS == 8) ? 3 : (NS == 16) ? 4 : (NS == 32) ? 5 : 0;
/* verilator lint_on UNUSEDPARAM */
generate
    if (LOG2NS == 0) begin : ns_check
        ef_error_NS_must_be_8_16_or_32 u_ns_must_be_8_16_or_32 ();
    end
endgenerate
