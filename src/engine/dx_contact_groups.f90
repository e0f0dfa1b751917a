!> Contact pairs kept whole by the partition (ParaDyn, issue 6; docs/history.md, "Parallel
!> contact"): dynx-part and the engine's partitioner condense each local contact pair (an
!> interface neither AUTOMATIC_ nor SINGLE_SURFACE) into one super element, so a pair lands
!> whole on one rank; the partition report says where each went. Moved out of dx_par_contact
!> (which re-exports both) to keep that module under 800 lines.
!> Strips and pairs: Hoover et al., ParaDyn, LLNL Engineering Thrust Area Report FY97
!> (article 4 of shared/seed).
module dx_contact_groups
   use dx_model, only: model_t
   use dx_contact_input, only: CT_SINGLE_SURFACE
   use dx_partition, only: face_elements, model_conn, partition_t
   implicit none
   private
   public :: contact_groups, write_contact_report

contains

   !> Element groups that must stay on one rank: one per local contact pair (interfaces
   !> neither AUTOMATIC_ nor SINGLE_SURFACE), the elements with a face on one of its
   !> surfaces (face_elements) or holding one of its slave nodes (node-set slaves). CSR:
   !> group g = grp_elem(grp_ptr(g):grp_ptr(g+1)-1); gid(g) the interface's label. Empty
   !> (grp_ptr = [1]) for a deck without such pairs.
   subroutine contact_groups(model, grp_ptr, grp_elem, gid, gif)
      type(model_t), intent(in) :: model
      integer, allocatable, intent(out) :: grp_ptr(:), grp_elem(:), gid(:)
      integer, allocatable, intent(out), optional :: gif(:)   !< interface index of each
      integer, allocatable :: conn(:, :), seg(:, :), elems(:), gi(:)
      logical, allocatable :: take(:), slave(:)
      integer :: i, j, e, ng
      allocate(grp_ptr(1), grp_elem(0), gid(0), gi(0))
      if (present(gif)) gif = gi
      grp_ptr(1) = 1
      if (.not. allocated(model%contact)) return
      call model_conn(model, conn)
      ng = 0
      do i = 1, size(model%contact%iface)
         associate (f => model%contact%iface(i))
            if (f%kind == CT_SINGLE_SURFACE) cycle
            if (index(f%name, 'AUTOMATIC') > 0) cycle
            allocate(seg(4, 0), take(model%ne), slave(model%nn))
            take = .false.
            slave = .false.
            do j = 1, size(f%pass)
               associate (p => f%pass(j))
                  seg = reshape([seg, p%seg(:, 1:p%nseg)], [4, size(seg, 2) + p%nseg])
                  if (p%nsseg > 0) then
                     seg = reshape([seg, p%sseg(:, 1:p%nsseg)], [4, size(seg, 2) + p%nsseg])
                  else
                     slave(p%node) = .true.
                  end if
               end associate
            end do
            call face_elements(conn, model%nn, seg, elems)
            take(elems) = .true.
            if (any(slave)) then
               do e = 1, model%ne
                  if (any(slave(conn(:, e)))) take(e) = .true.
               end do
            end if
            elems = pack([(e, e = 1, model%ne)], take)
            deallocate(seg, take, slave)
            if (size(elems) == 0) cycle
            ng = ng + 1
            grp_elem = [grp_elem, elems]
            grp_ptr = [grp_ptr, size(grp_elem) + 1]
            gid = [gid, f%label]
            gi = [gi, i]
            if (present(gif)) gif = gi
         end associate
      end do
   end subroutine contact_groups

   !> Partition report, contact part: where each local contact pair went.
   subroutine write_contact_report(unit, part, grp_ptr, grp_elem, gid)
      integer, intent(in) :: unit
      type(partition_t), intent(in) :: part
      integer, intent(in) :: grp_ptr(:), grp_elem(:), gid(:)
      integer :: k, r1, r2, w
      if (size(gid) == 0) return
      write(unit, '(a)') 'contact pairs kept whole (one super element each):'
      write(unit, '(a)') '  contact   elements     weight   rank(s)'
      do k = 1, size(gid)
         associate (el => grp_elem(grp_ptr(k):grp_ptr(k + 1) - 1))
            r1 = minval(part%epart(el))
            r2 = maxval(part%epart(el))
            w = sum(part%ewgt(el))
            if (r1 == r2) then
               write(unit, '(i9,2i11,3x,i0)') gid(k), size(el), w, r1
            else
               write(unit, '(i9,2i11,3x,i0,a,i0,a)') gid(k), size(el), w, r1, '..', r2, &
                  '  (split: pairs that share elements are merged)'
            end if
         end associate
      end do
   end subroutine write_contact_report
end module dx_contact_groups
