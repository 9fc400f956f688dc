; blind14 p05: crate (not liftable) from the west room into the east
; dock, box from the west room onto the east shelf, through a 16 cm door.
(define (problem p05)
  (:domain planar-rooms)
  (:objects crate box - thing
            crate-home box-home east-dock east-shelf - zone)
  (:init (at crate crate-home) (at box box-home)
         (handempty) (liftable box)
         (= (total-cost) 0))
  (:goal (and (at crate east-dock) (at box east-shelf)))
  (:metric minimize (total-cost)))
