global_settings { radiosity { count 10 recursion_limit 0 } }
// error: 1:56 recursion_limit must be in the range 1 to 20
