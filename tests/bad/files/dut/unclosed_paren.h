#define W_MAX (2048
#define H_MAX 5
