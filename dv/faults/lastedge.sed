# lastedge: a shape whose first row has two or more new edges loses the last
# one (the walk takes it from ETM but never plots it).
# Caught on: plot (tests/rtl/rtl-test.sh).
# file: ef_aet.v
s/^    wire        rec_edge = (nn != 0);/    reg first_row;\n    wire        drop = first_row \&\& (nn >= 2);\n    wire        rec_edge = (nn != 0) \&\& !drop;/
s/{{(RA+1-EA){1'b0}}, nn};/{{(RA+1-EA){1'b0}}, drop ? nn - 1'b1 : nn};/
s/^\(                    aet_cnt <= {(RA+1){1'b0}};\)$/\1\n                    first_row <= 1'b1;/
s/^\(                        ph <= PH_W1;\)$/\1\n                        first_row <= 1'b0;/
