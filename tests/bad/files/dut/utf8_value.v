parameter [31:0] W_MAX = 10, H_MAX = 2é0
