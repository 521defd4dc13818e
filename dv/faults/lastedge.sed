# lastedge: a shape whose first row has two or more new edges loses the last
# one (the walk takes it from ETM but never plots it).
# Caught on: plot (tests/rtl/rtl-test.sh).
# file: ef_aet.v
s/^    wire \[RA+1:0\] n_rd = {1'b0, n_old} + {{(RA+1-EA){1'b0}}, n_new_now};$/    reg first_row;\n    wire drop = first_row \&\& (n_new_now != 0);\n    wire [RA+1:0] n_rd = {1'b0, n_old} + {{(RA+1-EA){1'b0}}, n_new_now} - {{(RA+1){1'b0}}, drop};/
s/^                nn_nz <= 1'b1;$/                nn_nz <= !drop;/
s/^\(                    aet_cnt <= {(RA+1){1'b0}};\)$/\1\n                    first_row <= 1'b1;/
s/^\(                        ph <= PH_W1;\)$/\1\n                        first_row <= 1'b0;/
