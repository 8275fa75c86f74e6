"${CGAL_DATA_DIR}/meshes/spot_quadrangulated.obj" spot_moved.obj --random 20 --seed 1
