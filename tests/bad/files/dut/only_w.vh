// a canvas needs both
`define W_MAX 10
`define E_MAX 10
