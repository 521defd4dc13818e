#define MY_W_MAX 100
#define MY_H_MAX (50)
#define MY_E_MAX 64 /* edges */
#define MY_NS 16
