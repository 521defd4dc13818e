localparam W_MAX = 10
localparam W_MAX = 11
localparam H_MAX = 5
