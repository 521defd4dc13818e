#define W_MAX 10
#define H_MAX 0
