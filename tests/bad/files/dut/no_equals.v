parameter W_MAX 10
