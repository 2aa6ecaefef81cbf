echo "bad_input: TODO"
