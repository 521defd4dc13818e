`define W_MAX 10 + 1
`define H_MAX 10
