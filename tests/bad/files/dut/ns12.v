module dut;
    parameter integer W_MAX = 10, H_MAX = 20, E_MAX = 5;
    parameter NS = 12;
endmodule
