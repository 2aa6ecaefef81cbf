echo "scenes: TODO"
