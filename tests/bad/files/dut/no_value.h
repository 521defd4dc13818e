#define NS
