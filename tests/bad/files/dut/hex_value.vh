`define W_MAX 0x800
`define H_MAX 1024
