  parameter W_MAX = 32'd100,
  parameter H_MAX = 100
